#include "cable_dynamics/ros/output_source.h"

#include <cmath>
#include <stdexcept>

namespace cable_dynamics {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

bool finite(const PoseVector& poses) {
  for (const Pose& p : poses) {
    if (!p.position.allFinite() || !p.orientation.coeffs().allFinite()) return false;
  }
  return true;
}

bool finite(const SimulationSnapshot& s) {
  const ChainOutputs& c = s.chain;
  return std::isfinite(s.time) && s.q.allFinite() && s.qd.allFinite() && c.ends.allFinite() && c.tension.allFinite() &&
         finite(c.load_force) && finite(c.base_force) && finite(c.coupling_force) && std::isfinite(c.kinetic_energy) &&
         std::isfinite(c.potential_energy) && std::isfinite(c.elastic_energy) && s.axes.allFinite() &&
         s.twists.allFinite() && std::isfinite(s.dissipated_energy) && std::isfinite(s.work_input) &&
         std::isfinite(s.total_energy) && std::isfinite(s.deployed_length) && std::isfinite(s.winch_speed) &&
         std::isfinite(s.line_pull) && s.first_link >= 0 && s.first_link < s.chain.tension.size() &&
         finite(s.link_frames) && finite(s.after_azimuth) && finite(s.after_elevation);
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
  // The joint springs' dV/dq and the link frames as the simulator computed them (with the clamps where
  // the ends have them, at the stretched lengths): one computation for the model and the messages.
  out.spring_force = out.snapshot.chain.spring_force;
  return out.spring_force.allFinite();
}

}  // namespace cable_dynamics
