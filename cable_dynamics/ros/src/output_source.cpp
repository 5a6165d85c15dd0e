#include "cable_dynamics/ros/output_source.h"

#include <cmath>
#include <stdexcept>

namespace cable_dynamics {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

bool finite(const SimulationSnapshot& s) {
  const ChainOutputs& c = s.chain;
  return std::isfinite(s.time) && s.q.allFinite() && s.qd.allFinite() && c.ends.allFinite() && c.tension.allFinite() &&
         finite(c.load_force) && finite(c.base_force) && finite(c.coupling_force) && std::isfinite(c.kinetic_energy) &&
         std::isfinite(c.potential_energy) && std::isfinite(c.elastic_energy) && s.axes.allFinite() &&
         s.twists.allFinite() && std::isfinite(s.dissipated_energy) && std::isfinite(s.work_input) &&
         std::isfinite(s.total_energy) && std::isfinite(s.deployed_length) && std::isfinite(s.winch_speed) &&
         std::isfinite(s.line_pull) && s.first_link >= 0 && s.first_link < s.chain.tension.size();
}

bool finite(const PoseVector& poses) {
  for (const Pose& p : poses) {
    if (!p.position.allFinite() || !p.orientation.coeffs().allFinite()) return false;
  }
  return true;
}

}  // namespace

bool readOutputs(CableSimulator& sim, OutputSource& out) {
  try {
    sim.snapshot(out.snapshot);
  } catch (const std::runtime_error&) {  // the state cannot be evaluated
    return false;
  }
  if (!finite(out.snapshot)) return false;
  WinchReading& w = out.winch;
  w.present = sim.hasWinch();
  w.targeting = w.present && sim.winch().targeting();
  w.commanded_speed = w.present ? sim.winch().commandedSpeed() : 0.0;
  w.target_length = w.present ? sim.winch().targetLength() : 0.0;
  w.links_added = sim.linksAdded();
  w.links_removed = sim.linksRemoved();
  const int n = sim.links();
  if (out.alpha_hint.size() != n) out.alpha_hint = Eigen::VectorXd::Zero(n);
  // The joint springs' dV/dq as the dynamics computed them, with the clamps where the ends have them (a
  // clamp turning with the vessel or the ROV): one computation for the model and the message.
  out.spring_force = out.snapshot.chain.spring_force;
  // Each link's frame at its base end: the levers are the links' lengths, stretched with axial elasticity
  // (the frames then sit on the snapshot's ends; with the unstretched lengths they drifted by the stretches).
  if (out.levers.size() != n) out.levers.resize(n);  // the first reading only
  out.levers = sim.properties().length;
  if (out.snapshot.chain.stretch.size() == n) out.levers += out.snapshot.chain.stretch;
  linkFrames(out.snapshot.axes, out.snapshot.twists, out.snapshot.chain.ends.col(0), out.levers, out.links,
             out.after_azimuth, out.after_elevation, out.alpha_hint);
  if (!out.alpha_hint.allFinite()) out.alpha_hint.setZero();  // never let a bad hint outlive this instant
  return out.spring_force.allFinite() && finite(out.links) && finite(out.after_azimuth) &&
         finite(out.after_elevation);
}

}  // namespace cable_dynamics
