#include "cable_dynamics/simulation/cable_simulator.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/params/states.h"

namespace cable_dynamics {
namespace {

/// Largest change of the energy balance one step may make, relative to the energy scale [-].
constexpr double kEnergyTolerance = 1e-4;

/// Position, velocity and acceleration of a prescribed motion at time t, converted to the paper frame.
void motionAt(const MotionParams& m, double t, Eigen::Vector3d& p, Eigen::Vector3d& v, Eigen::Vector3d& a) {
  const double w = 2.0 * M_PI / m.period;
  p = worldToPaper(m.offset + m.amplitude * std::sin(w * t) + m.velocity * t);
  v = worldToPaper(m.amplitude * (w * std::cos(w * t)) + m.velocity);
  a = worldToPaper(m.amplitude * (-w * w * std::sin(w * t)));
}

}  // namespace

namespace {

/// The paper's azimuth and torsion springs and dampers act on angles that are not defined when a link
/// hangs straight down; their torque grows like 1/sin(te) there (docs/MODEL.md section 5).
void rejectSingularPaperSprings(const CableParams& p) {
  if (p.stiffness.model != StiffnessModel::kPaper) return;
  const std::pair<const char*, double> values[] = {
      {"cable.stiffness.azimuth", p.stiffness.azimuth},        {"cable.stiffness.torsion", p.stiffness.torsion},
      {"cable.stiffness.torsional_rigidity", p.stiffness.torsional_rigidity},
      {"cable.stiffness.bending_rigidity", p.stiffness.bending_rigidity},
      {"cable.damping.azimuth", p.damping.azimuth},            {"cable.damping.torsion", p.damping.torsion}};
  for (const auto& [key, value] : values) {
    if (value != 0.0) {
      throw std::invalid_argument(std::string(key) + " = " + std::to_string(value) +
                                  ": expected 0 with cable.stiffness.model: paper in the simulator (the paper's "
                                  "azimuth and torsion springs and dampers are singular at the vertical); use "
                                  "model: bending");
    }
  }
  // The paper's elevation damper acts along the azimuth's direction, which swings fast as a link passes
  // near the vertical: the semi-implicit step, which holds directions over a long step, mis-tracks it
  // (measured: a 10 ms step stalls the current preset away from its steady state). RK4 tracks it.
  if (p.simulation.integrator == "semi_implicit" && p.damping.elevation != 0.0) {
    throw std::invalid_argument("cable.damping.elevation = " + std::to_string(p.damping.elevation) +
                                ": expected 0 with simulation.integrator: semi_implicit unless "
                                "cable.stiffness.model is bending (or use integrator: rk4)");
  }
}

}  // namespace

CableSimulator::CableSimulator(const CableParams& params)
    : params_(params),
      dynamics_(params),
      dt_(params.simulation.dt),
      semi_implicit_(params.simulation.integrator == "semi_implicit") {
  rejectSingularPaperSprings(params);
  const int size = dynamics_.stateSize();
  for (Eigen::VectorXd* v : {&x_, &x_start_, &k1_, &k2_, &k3_, &k4_, &stage_}) v->setZero(size);
  q_.setZero(3 * params.links);
  qd_.setZero(3 * params.links);
  // A step that spins a link faster than this has diverged: 1000 x the swing rate of the shortest link
  // as a pendulum (and at least 1000 rad/s).
  const double shortest = dynamics_.properties().length.minCoeff();
  omega_limit_ = std::max(1000.0, 1000.0 * std::sqrt(std::max(params.gravity, 1.0) / shortest));
  reset();
}

void CableSimulator::reset() {
  Eigen::VectorXd q, qd;
  initialState(params_, q, qd);
  external_load_ = false;
  external_base_ = false;
  dynamics_.current() = CurrentField(params_.fluid);
  setPaperState(q, qd);
}

void CableSimulator::recover() {
  const double t = time_;
  Eigen::VectorXd q, qd;
  initialState(params_, q, qd);
  setPaperState(q, qd);
  time_ = t;
}

void CableSimulator::setPaperState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const int dof = 3 * links();
  if (q.size() != dof || qd.size() != dof) {
    throw std::invalid_argument("state has " + std::to_string(q.size()) + " positions and " +
                                std::to_string(qd.size()) + " velocities: expected 3n = " + std::to_string(dof));
  }
  if (!q.allFinite() || !qd.allFinite()) throw std::invalid_argument("state has a non-finite value");
  dynamics_.stateFromPaper(q, qd, x_);
  start_cached_ = false;
  // Continue azimuths from the given angles (straight-down links keep the azimuth they were given).
  Eigen::VectorXd psi(links());
  double sum = 0.0;
  for (int k = 0; k < links(); ++k) psi(k) = (sum += q(3 * k + 1));
  dynamics_.setAzimuthReference(psi);
  time_ = 0.0;
  Eigen::Vector3d position, velocity, acceleration;
  motionAt(params_.base.motion, 0.0, position, velocity, acceleration);
  Eigen::Vector3d tip = position;
  for (int k = 0; k < links(); ++k) tip += dynamics_.properties().length(k) * x_.segment<3>(StateLayout::axis(k));
  initial_tip_ = tip;
}

EndInputs CableSimulator::endsAt(double t) const {
  EndInputs ends;
  if (external_base_) {
    ends.base_position = base_target_pos_;
    ends.base_velocity = base_target_vel_;
  } else {
    motionAt(params_.base.motion, t, ends.base_position, ends.base_velocity, ends.base_acceleration);
  }
  ends.load_coupled = params_.load.mode != LoadMode::kFree;
  if (external_load_) {
    ends.target_position = load_target_pos_;
    ends.target_velocity = load_target_vel_;
  } else if (ends.load_coupled) {
    Eigen::Vector3d a;
    motionAt(params_.load.motion, t, ends.target_position, ends.target_velocity, a);
    ends.target_position += initial_tip_;
    if (params_.load.mode == LoadMode::kAnchored) ends.target_velocity.setZero();
  }
  return ends;
}

double CableSimulator::energyBalance(const Eigen::VectorXd& x, double t, double& scale) {
  double magnitude = 0.0;
  return balance(x, dynamics_.mechanicalEnergy(x, endsAt(t), magnitude), magnitude, scale);
}

double CableSimulator::balance(const Eigen::VectorXd& x, double mechanical, double magnitude, double& scale) const {
  const int n = links();
  const double dissipated = x(StateLayout::dissipated(n)), work = x(StateLayout::workInput(n));
  scale = magnitude + std::abs(dissipated) + std::abs(work);
  return mechanical + dissipated - work;
}

bool CableSimulator::advance(double h) {
  ChainDynamics& f = dynamics_;
  const double t = time_;
  // The balance after the previous accepted step, and x' there, are the ones at the start of this one,
  // unless an input changed.
  double scale_before = cached_scale_;
  const bool start_known = start_cached_;
  const double balance_before = start_known ? cached_balance_ : energyBalance(x_, t, scale_before);
  start_cached_ = false;
  if (semi_implicit_) {
    if (!f.semiImplicitStep(x_, endsAt(t), h, stage_)) return false;
    x_ = stage_;
    time_ = t + h;
    return acceptable(balance_before, scale_before);
  }
  // Classical RK4 on x' = f(t, x).
  if (!start_known && !f.derivative(x_, endsAt(t), k1_)) return false;
  stage_ = x_ + 0.5 * h * k1_;
  if (!f.derivative(stage_, endsAt(t + 0.5 * h), k2_)) return false;
  stage_ = x_ + 0.5 * h * k2_;
  if (!f.derivative(stage_, endsAt(t + 0.5 * h), k3_)) return false;
  stage_ = x_ + h * k3_;
  if (!f.derivative(stage_, endsAt(t + h), k4_)) return false;
  x_ += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
  time_ = t + h;
  return acceptable(balance_before, scale_before);
}

bool CableSimulator::acceptable(double balance_before, double scale_before) {
  const int n = links();
  for (int k = 0; k < n; ++k) {
    auto axis = x_.segment<3>(StateLayout::axis(k));
    const double norm = std::sqrt(axis.squaredNorm());
    if (!std::isfinite(norm) || norm < 0.5) return false;
    axis *= 1.0 / norm;  // back onto the unit sphere
    if (!(x_.segment<3>(StateLayout::omega(k)).squaredNorm() < omega_limit_ * omega_limit_)) return false;
  }
  if (!std::isfinite(x_.sum())) return false;  // the twists and the energy accumulators
  // Kinetic + potential + elastic + dissipated - work input stays constant up to RK4's local error
  // (~1e-10 of the energy scale per step in the presets); an unstable mode shows as energy created.
  // The semi-implicit step balances energy only to first order (its power terms are taken at the start
  // of the step), so for it only the hard limits above apply.
  if (semi_implicit_) return true;
  // The energy after the step comes with the next step's first stage, x' at the new state: it is
  // evaluated here and advance() takes it as k1 (as the "first same as last" schemes reuse a stage),
  // unless an input changes in between. A state where x' is not finite fails here, not one step later.
  if (!dynamics_.derivative(x_, endsAt(time_), k1_)) return false;
  double magnitude = 0.0, scale_after = 0.0;
  const double mechanical = dynamics_.solvedMechanicalEnergy(x_, magnitude);
  const double balance_after = balance(x_, mechanical, magnitude, scale_after);
  const double scale = std::max(scale_before, scale_after) + 1e-9;
  if (balance_after - balance_before > kEnergyTolerance * scale) return false;
  start_cached_ = true;
  cached_balance_ = balance_after;
  cached_scale_ = scale_after;
  return true;
}

StepReport CableSimulator::step() {
  StepReport report;
  x_start_ = x_;
  const double t0 = time_;
  for (int pieces = 1; pieces <= 64; pieces *= 2) {
    bool ok = true;
    for (int i = 0; i < pieces && ok; ++i) ok = advance(dt_ / pieces);
    if (ok) {
      report.substeps = pieces;
      time_ = t0 + dt_;  // no drift from summing the pieces
      dynamics_.followAzimuths(x_);
      return report;
    }
    x_ = x_start_;
    time_ = t0;
    start_cached_ = false;
  }
  dynamics_.paperCoordinates(x_, q_, qd_);
  std::ostringstream message;
  message.precision(6);
  message << "step from t = " << t0 << " s diverged even in 64 substeps (dt = " << dt_
          << " s); state kept at t = " << t0 << " s: q = [" << q_.transpose() << "], qd = [" << qd_.transpose() << "]";
  report.ok = false;
  report.substeps = 64;
  report.message = message.str();
  return report;
}

void CableSimulator::snapshot(SimulationSnapshot& out) {
  out.time = time_;
  out.q.resize(3 * links());
  out.qd.resize(3 * links());
  dynamics_.paperCoordinates(x_, out.q, out.qd);
  if (!dynamics_.evaluate(x_, endsAt(time_), out.chain)) {
    throw std::runtime_error("snapshot: the state at t = " + std::to_string(time_) + " s is not valid");
  }
  out.axes.resize(3, links());
  out.twists.resize(links());
  for (int k = 0; k < links(); ++k) {
    out.axes.col(k) = x_.segment<3>(StateLayout::axis(k)).normalized();
    out.twists(k) = x_(StateLayout::twist(k));
  }
  out.dissipated_energy = x_(StateLayout::dissipated(links()));
  out.work_input = x_(StateLayout::workInput(links()));
  out.total_energy = out.chain.kinetic_energy + out.chain.potential_energy + out.chain.elastic_energy +
                     out.dissipated_energy - out.work_input;
}

void CableSimulator::setCurrent(const Eigen::Vector3d& current) {
  dynamics_.current().setUniformWorld(current);
  start_cached_ = false;
}

void CableSimulator::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  external_load_ = true;
  start_cached_ = false;
  load_target_pos_ = worldToPaper(position);
  load_target_vel_ = worldToPaper(velocity);
}

void CableSimulator::setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  external_base_ = true;
  start_cached_ = false;
  base_target_pos_ = worldToPaper(position);
  base_target_vel_ = worldToPaper(velocity);
}

double CableSimulator::estimateStableTimeStep() const {
  const LinkProperties& p = dynamics_.properties();
  const int n = p.n;
  const double radius = 0.5 * params_.diameter;
  const double added = params_.fluid.added_mass * params_.fluid.density * M_PI * radius * radius;  // [kg/m]
  // Hanging tension at the top: submerged weight of everything below, or the load's alone if larger.
  const double tension = std::abs(p.gravity * (p.submerged_mass.sum() + p.load_submerged_mass)) +
                         params_.load.coupling_stiffness * (params_.load.mode == LoadMode::kFree ? 0.0 : p.length.maxCoeff());
  double omega_max = 0.0;
  for (int k = 0; k < n; ++k) {
    const double l = p.length(k), m = p.mass(k) + added * l;
    // Highest mode of a beaded string: 2 sqrt(T / (m l)) for links of mass m and length l.
    omega_max = std::max(omega_max, 2.0 * std::sqrt(tension / (m * l)));
    const double k_bend = std::max(p.stiffness_elevation(k), p.stiffness_azimuth(k));
    omega_max = std::max(omega_max, std::sqrt(4.0 * k_bend / (p.mass(k) * l * l / 12.0)));
    omega_max = std::max(omega_max, std::sqrt(4.0 * p.stiffness_torsion(k) / p.inertia_polar(k)));
  }
  // RK4 is stable for dt * omega < 2.8 on oscillatory modes; keep a factor 2 of margin.
  return omega_max > 0.0 ? 1.4 / omega_max : std::numeric_limits<double>::infinity();
}

}  // namespace cable_dynamics
