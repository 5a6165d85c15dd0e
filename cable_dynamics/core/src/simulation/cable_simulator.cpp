#include "cable_dynamics/simulation/cable_simulator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/dynamics/rov_body.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/params/states.h"
#include "cable_dynamics/simulation/winch_links.h"

namespace cable_dynamics {
void checkSimulatorInputs(const CableParams& params, const LinkProperties& properties, SimulatorUse use) {
  checkConfigRules(params);
  checkSimulatorRules(params);
  if (use == SimulatorUse::kStepping) requireStableTimeStep(params, properties);  // not for the two others
}

namespace {
/// `p`, once each value is within its key's range: before any member is built from it (a link count or
/// a list size out of range would otherwise reach an allocation or an index first).
const CableParams& inRange(const CableParams& p) {
  checkConfigRanges(p);
  return p;
}
}  // namespace

CableSimulator::CableSimulator(const CableParams& configured, SimulatorUse use)
    : params_(ChainModel::withDrumSlots(inRange(configured))),
      use_(use),
      dynamics_(params_),
      scheme_(makeTimeScheme(params_.simulation.integrator, params_.links, params_.simulation.rho_infinity,
                             params_.load.mode == LoadMode::kBody, params_.stretches())),
      ends_(params_.base, params_.load, params_.winch),
      limits_(stepLimits(*std::min_element(params_.link_lengths.begin(), params_.link_lengths.end()), params_.gravity)),
      dt_(params_.simulation.dt) {
  checkSimulatorInputs(params_, dynamics_.properties(), use);  // the gate: refused before anything runs
  ends_.setRestClamp(dynamics_.properties().clamp_axis, dynamics_.properties().clamp_twist);
  const int size = dynamics_.stateSize();
  x_.setZero(size);
  x_start_.setZero(size);
  slack_.assign(params_.links, 1);
  alpha_hint_.setZero(params_.links);
  levers_.setZero(params_.links);
  q_.setZero(3 * params_.links);
  qd_.setZero(3 * params_.links);
  reset();
}

void CableSimulator::reset() {
  Eigen::VectorXd q, qd;
  initialState(params_, q, qd);
  ends_.reset();
  if (hasWinch()) ends_.winch().reset(params_.deployedLength());
  deployConfigured();
  links_added_ = links_removed_ = 0;
  regrid_energy_ = 0.0;
  largest_tension_ = 0.0;
  snaps_ = 0;
  dynamics_.current() = CurrentField(params_.fluid);
  setPaperState(q, qd);
  if (params_.load.heldExactly() && params_.initial.mode != InitialMode::kEquilibrium && use_ != SimulatorUse::kStaticsOnly) {
    // The anchor is placed relative to the starting shape's tip: a start from the angles is on it only when
    // load.motion puts it there at t = 0 (a hold that yanked the tip across would be no physics).
    const MotionParams& m = params_.load.motion;
    const Eigen::Vector3d away = m.offset + m.amplitude * std::sin(m.phase);
    if (away.norm() > 0.0) {
      throw ConfigError("initial.mode", "angles",
                        "equilibrium with an exact anchor away from the starting tip (load.motion puts it " +
                            formatNumber(away.norm()) + " m from it at t = 0)");
    }
  }
  if (params_.initial.mode == InitialMode::kEquilibrium) {
    const StaticSolution s = resetToEquilibrium();
    if (!s.converged) throw std::runtime_error("initial.mode = equilibrium: " + s.message);
  } else if (params_.load.heldExactly() && use_ != SimulatorUse::kStaticsOnly) {
    dynamics_.matchTipVelocity(x_, ends_.at(time_));  // as resetToEquilibrium: a base that starts moving
  }
  watchStretches(false);  // the start's slack links and tension
  commanded_thrust_.setZero();
  applied_thrust_.setZero();
  keeper_integral_.setZero();
  if (hasBody()) {  // the station keeper holds the start pose until told otherwise
    const BodyPose pose = bodyPose();
    body_target_position_ = pose.position;
    body_target_attitude_ = pose.attitude;
  }
}

namespace {
/// The world frame's rotation from the ROV body's axes, from the paper frame's `paper_from_body`: the half
/// turn about x (frames.h) after it.
Eigen::Quaterniond bodyPoseAttitude(const Eigen::Matrix3d& paper_from_body) {
  const Eigen::Matrix3d world_from_body = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal() * paper_from_body;
  return Eigen::Quaterniond(world_from_body).normalized();
}
}  // namespace

BodyPose CableSimulator::bodyPose() {
  BodyPose pose;
  if (!hasBody()) return pose;
  dynamics_.computeBodyPose(x_, ends_.at(time_));
  const ChainData& data = dynamics_.data();
  const RovBodyTerms& body = data.body;
  pose.position = paperToWorld(rovBodyOrigin(dynamics_.model().body(), body.rotation, data.tip_position));
  pose.attitude = bodyPoseAttitude(body.rotation);
  pose.velocity = paperToWorld(body.rotation * body.velocity.head<3>());
  pose.angular_velocity = body.omega;
  return pose;
}

void CableSimulator::setBodyThrust(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  if (!hasBody()) throw std::invalid_argument("body thrust: load.mode is not body (no ROV body is simulated)");
  checkThrust("body thrust force", force);
  checkThrust("body thrust torque", torque);
  commanded_thrust_ << force, torque;
}

void CableSimulator::setBodyTarget(const Eigen::Vector3d& position, const Eigen::Quaterniond& attitude) {
  if (!hasBody()) throw std::invalid_argument("body target: load.mode is not body (no ROV body is simulated)");
  checkPosition("body target position", position);
  checkAttitude("body target attitude", attitude);
  body_target_position_ = position;
  body_target_attitude_ = attitude;
}

void CableSimulator::updateBodyThrust() {
  Eigen::Matrix<double, 6, 1> thrust = commanded_thrust_;
  const RovBodyParams& keeper = params_.load.body;
  if (stationKeepingEnabled(keeper)) {
    const double submerged_weight = (params_.load.mass - params_.fluid.density * params_.load.volume) * params_.gravity;
    thrust += stationKeepingWrench(keeper, submerged_weight, bodyPose(), body_target_position_, body_target_attitude_,
                                   dt_, keeper_integral_);
  }
  if (thrust == applied_thrust_) return;
  applied_thrust_ = thrust;
  ends_.setBodyThrust(thrust);
  scheme_->forgetRates();  // RK4's first stage was evaluated under the old thrust
}

StaticSolution CableSimulator::resetToEquilibrium(const StaticOptions& options) {
  ends_.setHoldOffset(Eigen::Vector3d::Zero());  // the statics hold the anchor itself
  const EndInputs ends = ends_.at(time_);
  StaticProblem problem;
  problem.base_position = ends.base_position;
  problem.tip_coupled = ends.load_coupled;
  problem.target_position = ends.target_position;
  problem.first_link = firstLink();
  problem.clamp_moves = ends.clamp_moves;
  problem.clamp_axis = ends.clamp_axis;
  problem.clamp_twist = ends.clamp_twist;
  problem.tip_clamp_moves = ends.tip_clamp_moves;
  problem.tip_clamp_axis = ends.tip_clamp_axis;
  dynamics_.applyEnds(ends);  // the winch's link at its present length
  StaticSolution s = solveStatics(dynamics_.model(), dynamics_.deployed(), dynamics_.current(), problem, options);
  // With the coupling's integral action the equilibrium has the tip on the target and the spring's rest
  // point shifted by the tension over k: the statics move their target by the tip's miss until it is under
  // kIntegralStaticsTolerance (each pass shrinks the miss by K / (k + K), K the cable's own stiffness at its
  // end), and the dynamics' integral takes over what is left.
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  if (ends_.couplingIntegral() && ends.load_coupled && !dynamics_.model().heldTip()) {
    for (int pass = 0; pass < kIntegralStaticsPasses && s.converged; ++pass) {
      const Eigen::Vector3d miss = s.tip_position - ends.target_position;
      if (miss.norm() <= kIntegralStaticsTolerance) break;
      shift -= miss;
      problem.target_position = ends.target_position + shift;
      s = solveStatics(dynamics_.model(), dynamics_.deployed(), dynamics_.current(), problem, options);
    }
  }
  if (!s.converged) return s;  // the state and the coupling's rest shift stay as they were
  ends_.shiftCouplingRest(shift, time_);  // the statics' own extension (zero without the integral action)
  const int n = links();
  setRestState(s, x_);
  // A base that starts moving under the chain at rest moves the tip with it: the exact anchor's start is
  // corrected by the impulse that keeps the tip with the anchor (the least kinetic energy that does).
  if (params_.load.heldExactly()) dynamics_.matchTipVelocity(x_, ends);
  // The implicit steps' spring hold starts with the anchor's reaction, its rest point beyond the anchor, so
  // that the run starts with the tip on the anchor and no transient; it then gives by the change of the
  // anchor's force over k_h (moving its rest point after each step by the tip's miss, an integral action,
  // rang with the stiff mode, which the implicit step damps only by rho_infinity a step, and diverged).
  if (params_.load.heldExactly() && !dynamics_.model().heldTip()) {
    ends_.setHoldOffset(s.hold_force / dynamics_.model().load().coupling_stiffness);
  }
  watchStretches(false);
  x_(StateLayout::dissipated(n)) = 0.0;
  x_(StateLayout::workInput(n)) = 0.0;
  // Azimuths continue from the solved axes (nearest branch to the old ones); a new start for the
  // energy bookkeeping, as after setPaperState().
  dynamics_.followAzimuths(x_);
  dynamics_.releaseJoints();  // the equilibrium holds no joint
  // The frictionless equilibrium is one the static friction allows: its anchors where the points rest.
  dynamics_.placeContactAnchors(x_, ends_.at(time_), false);
  startAfresh();
  // The winch keeps running at its speed (stopping it in one step broke its acceleration limit).
  if (hasWinch()) ends_.winch().moveTo(ends_.winch().motion().length);
  return s;
}

void CableSimulator::recover() {
  const double t = time_;
  Eigen::VectorXd q, qd;
  initialState(params_, q, qd);
  if (hasWinch()) ends_.winch().restart(params_.deployedLength());  // its command carries on
  deployConfigured();
  setPaperState(q, qd);
  time_ = t;
  // An exact anchor holds a tip that starts on it: the equilibrium again, where the run started from one
  // (its angles' tip is not on the anchor); the angles when the statics fail there.
  if (params_.load.heldExactly() && params_.initial.mode == InitialMode::kEquilibrium && !resetToEquilibrium().converged) {
    setPaperState(q, qd);
    time_ = t;
  }
}

void CableSimulator::deployConfigured() {
  if (!hasWinch()) return;
  const int first = params_.drumSlots();
  dynamics_.deploy(first);
  ends_.setOutboardLength(params_.deployedLength() - params_.link_lengths[first]);
}

void CableSimulator::commandWinchSpeed(double speed) {
  if (!hasWinch()) throw std::invalid_argument(kNoWinchMessage);
  checkWinchSpeed(speed, params_.winch);
  ends_.winch().commandSpeed(speed);
  ends_.winch().cancelSchedule();  // the operator's command replaces the configured schedule
}

void CableSimulator::commandWinchLength(double length) {
  if (!hasWinch()) throw std::invalid_argument(kNoWinchMessage);
  checkWinchLength(length, params_.winch);
  ends_.winch().commandLength(length);
  ends_.winch().cancelSchedule();
}

double CableSimulator::deployedLength() const {
  return hasWinch() ? ends_.winch().motion().length : params_.totalLength();
}

void CableSimulator::finishWinchStep() {
  Winch& winch = ends_.winch();
  winch.finish(time_);
  const EndInputs before = ends_.at(time_);
  // The energy evaluations below only where a link is added or removed.
  if (winchRegridDue(dynamics_.deployed(), before.winch_length, params_.winch.link_length) == WinchRegrid::kNone) return;
  double magnitude = 0.0, outboard = ends_.outboardLength();
  const double energy_before = dynamics_.mechanicalEnergy(x_, before, magnitude);
  const WinchRegrid change = regridWinchLinks(dynamics_, x_, before.winch_length, params_.winch.link_length,
                                              before.winch_speed, outboard);
  if (change == WinchRegrid::kNone) return;
  (change == WinchRegrid::kAdded ? links_added_ : links_removed_) += 1;
  ends_.setOutboardLength(outboard);
  // A link added: the new joint starts with the moment the rigid link held there and lets it go as the
  // next link is paid out (docs/MODEL.md section 8), so the line pull goes on from where it was.
  if (change == WinchRegrid::kAdded) {
    const int joint = firstLink() + 1;
    dynamics_.holdNewJoint(joint, x_, ends_.at(time_), dynamics_.properties().length(joint),
                           std::min(kJointHoldDampingRate, kJointHoldDampingStep / dt_));
  }
  // What the change took out of the mechanical energy (nothing when a link is added; the kink's
  // energy when two merge) counts as dissipated, so that the balance stays closed.
  const double energy_after = dynamics_.mechanicalEnergy(x_, ends_.at(time_), magnitude);
  x_(StateLayout::dissipated(links())) += energy_before - energy_after;
  regrid_energy_ += energy_before - energy_after;
  dynamics_.followAzimuths(x_);
  // The split or merged link's anchors afresh (the kinematics are the new state's: the energy above).
  dynamics_.slideContactAnchors(2);
  start_balance_known_ = false;
  scheme_->forget();
}

void CableSimulator::watchStretches(bool count_snaps) {
  const ChainModel& model = dynamics_.model();
  if (!model.axial()) return;
  const int n = links();
  const bool body = hasBody();
  const int first = dynamics_.deployed().firstLink();
  const double winch_speed = hasWinch() ? ends_.winch().motion().speed : 0.0;
  for (int k = first; k < n; ++k) {
    if (model.stretchLocked(k)) continue;
    const int i = LinkBlocks::lane(k);
    const double s = x_(StateLayout::stretch(n, body, k)), rate = x_(StateLayout::stretchRate(n, body, k));
    const LinkConstants& c = dynamics_.deployed().of(k);
    const double damped = k == first ? AxialSpring::dampedRate(s, rate, c.length[i], winch_speed) : rate;
    largest_tension_ = std::max(largest_tension_, AxialSpring::tension(c.axial_stiffness[i], c.axial_damping[i], s, damped, c.length[i]));
    // A snap: a link shorter than unstretched by more than 0.1 % of its length that comes taut. The
    // margin keeps a taut line's light links, ringing about s = 0 after a snap, from counting each crossing.
    if (s < -kClearlySlack * c.length[i]) {
      slack_[k] = 1;
    } else if (s >= 0.0) {
      if (count_snaps && slack_[k]) ++snaps_;
      slack_[k] = 0;
    }
  }
}

void CableSimulator::startAfresh() {
  start_balance_known_ = false;
  drift_reference_known_ = false;
  largest_scale_ = energy_drift_ = energy_rise_ = 0.0;
  alpha_hint_.setZero();  // a new state: the URDF's frames start afresh
  startup_pieces_ = kStartupPieces;
  scheme_->forget();
}

void CableSimulator::setState(const Eigen::VectorXd& x) {
  if (x.size() != x_.size()) {
    throw std::invalid_argument("state has " + std::to_string(x.size()) + " entries: expected " +
                                std::to_string(x_.size()) + " (dynamics/state_layout.h)");
  }
  if (!x.allFinite()) throw std::invalid_argument("state has a non-finite value");
  x_ = x;
  dynamics_.followAzimuths(x_);
  dynamics_.placeContactAnchors(x_, ends_.at(time_), false);
  watchStretches(false);  // the new state's slack links, without counting a snap
  startAfresh();
}

void CableSimulator::setPaperState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const int dof = 3 * links();
  if (q.size() != dof || qd.size() != dof) {
    throw std::invalid_argument("state has " + std::to_string(q.size()) + " positions and " +
                                std::to_string(qd.size()) + " velocities: expected 3n = " + std::to_string(dof));
  }
  if (!q.allFinite() || !qd.allFinite()) throw std::invalid_argument("state has a non-finite value");
  dynamics_.stateFromPaper(q, qd, x_);
  dynamics_.releaseJoints();  // a new state: no joint is held
  startAfresh();
  retried_steps_ = 0;
  // Continue azimuths from the given angles (straight-down links keep the azimuth they were given).
  Eigen::VectorXd psi(links());
  double sum = 0.0;
  for (int k = 0; k < links(); ++k) psi(k) = (sum += q(3 * k + 1));
  dynamics_.setAzimuthReference(psi);
  time_ = 0.0;
  Eigen::Vector3d position, velocity, acceleration;
  motionAt(params_.base.motion, params_.base.hang_off, 0.0, position, velocity, acceleration);
  Eigen::Vector3d tip = position;
  for (int k = 0; k < links(); ++k) tip += properties().length(k) * x_.segment<3>(StateLayout::axis(k));
  ends_.setInitialTip(tip);
  dynamics_.placeContactAnchors(x_, ends_.at(time_), false);
}

EnergyBalance CableSimulator::balanceNow() {
  double magnitude = 0.0;
  const double mechanical = dynamics_.mechanicalEnergy(x_, ends_.at(time_), magnitude);
  return energyBalance(mechanical, magnitude, x_, links());
}

bool CableSimulator::advance(double h) {
  const int n = links();
  // The balance after the previous accepted step is the one at the start of this one, unless an input
  // changed.
  const EnergyBalance before = start_balance_known_ ? start_balance_ : balanceNow();
  start_balance_known_ = false;
  refused_energy_ = 0.0;
  refusal_ = "the integrator's state was not finite";
  if (!scheme_->advance(dynamics_, ends_, time_, h, x_)) return false;
  time_ += h;
  refusal_ = "a link's axis lost its length";
  if (!projectAxes(x_, n, firstLink())) return false;  // the links on a winch's drum do not move
  if (dynamics_.model().body().active) {  // the ROV's quaternion back to unit length
    auto attitude = x_.segment<4>(StateLayout::bodyAttitude(n));
    const double norm = attitude.norm();
    refusal_ = "the ROV's attitude lost its unit length";
    if (!(norm > 0.5 && norm < 2.0)) return false;
    attitude /= norm;
  }
  const StepVerdict state_verdict = judgeStep(x_, n, limits_, firstLink());
  refusal_ = verdictName(state_verdict);
  if (state_verdict != StepVerdict::kAccepted) return false;
  EnergyBalance after;
  if (scheme_->balancesEnergy()) {
    // The energy after the step comes from an evaluation at the new state (which RK4 keeps as the next
    // step's first stage). A state where x' is not finite fails here, not one step later.
    refusal_ = "the rates at the new state were not finite";
    if (!scheme_->evaluateEnd(dynamics_, ends_.at(time_), x_)) return false;
    double magnitude = 0.0;
    const double mechanical = dynamics_.solvedMechanicalEnergy(x_, magnitude);
    after = energyBalance(mechanical, magnitude, x_, n);
    if (!acceptEnergy(before, after, limits_.energy_tolerance)) return false;
  } else {
    // Followed at every step, so that no sampling of the output hides a rise, and (the implicit step) judged
    // against the looser tolerance of a second-order balance: what that catches is an event within the
    // step, such as a point touching down on the bed's stiff spring between the two stages.
    after = balanceNow();
    refusal_ = "a non-finite energy";
    if (!std::isfinite(after.value)) return false;
    if (!acceptEnergy(before, after, scheme_->riseTolerance(limits_))) return false;
  }
  // The balance after this step is the next one's start; the drift (RK4) and the rise (implicit) since reset.
  start_balance_ = after;
  start_balance_known_ = true;
  if (!drift_reference_known_) {
    drift_reference_ = before.value;
    drift_reference_known_ = true;
  }
  largest_scale_ = std::max({largest_scale_, before.mechanical, after.mechanical, 1e-9});
  const double change = (after.value - drift_reference_) / largest_scale_;
  energy_drift_ = std::max(energy_drift_, std::abs(change));
  energy_rise_ = std::max(energy_rise_, change);
  return true;
}

bool CableSimulator::acceptEnergy(const EnergyBalance& before, const EnergyBalance& after, double tolerance) {
  const StepVerdict verdict = judgeEnergy(before, after, tolerance);
  if (verdict == StepVerdict::kAccepted) return true;
  refusal_ = verdictName(verdict);
  refused_energy_ = after.value - before.value;
  refused_scale_ = std::max(before.mechanical, after.mechanical);
  refused_tolerance_ = tolerance;
  return false;
}

StepReport CableSimulator::step() {
  if (use_ == SimulatorUse::kStaticsOnly) {
    throw std::logic_error("step: this simulator was built for its statics only (its time step was not checked)");
  }
  StepReport report;
  const int moving = StateLayout::moving(x_.size(), firstLink());  // a winch's drum slots do not change in a step
  x_start_.tail(moving) = x_.tail(moving);
  const double t0 = time_;
  if (hasBody()) updateBodyThrust();
  if (hasWinch()) {
    Winch& winch = ends_.winch();
    winch.followSchedule(t0);
    if (winch.plan(t0, dt_)) scheme_->forget();  // a new acceleration: the last stage is not this step's
  }
  // The first step from a new state is planned in pieces (RK4, whose balance is judged per step): a start
  // from rest into a flow or a moving end excites the stiffest modes at once, and at the recommended step
  // (half the stable limit, h lambda = 1.4) RK4 is stable but its first step's balance is off by more than
  // the tolerance (paper_current: 0.93 J of a 3675 J scale, against 0.37 J), so it was retried.
  const int planned = scheme_->balancesEnergy() ? startup_pieces_ : 1;
  for (int pieces = planned; pieces <= kMaxSubsteps; pieces *= 2) {
    bool ok = true;
    for (int i = 0; i < pieces && ok; ++i) ok = advance(dt_ / pieces);
    if (ok) {
      report.substeps = pieces / planned;
      if (pieces > planned) ++retried_steps_;
      startup_pieces_ = 1;
      time_ = t0 + dt_;  // no drift from summing the pieces
      dynamics_.followAzimuths(x_);
      dynamics_.slideContactAnchors();  // at the kinematics advance() left: the new state's
      integrateCouplingRest();          // at the same kinematics
      if (hasWinch()) {
        dynamics_.dropReleasedHolds(ends_.at(time_));
        finishWinchStep();
      }
      watchStretches(true);
      return report;
    }
    x_.tail(moving) = x_start_.tail(moving);
    time_ = t0;
    start_balance_known_ = false;
    scheme_->forget();
  }
  dynamics_.paperCoordinates(x_, q_, qd_);
  std::ostringstream message;
  message.precision(6);
  message << "step from t = " << t0 << " s diverged even in " << kMaxSubsteps << " substeps (dt = " << dt_
          << " s; the last substep refused for " << refusal_;
  if (refused_energy_ != 0.0) {
    message << ": " << refused_energy_ << " J in one substep, over " << refused_tolerance_ << " of the scale "
            << refused_scale_ << " J";
  }
  message << "); state kept at t = " << t0 << " s: q = [" << q_.transpose() << "], qd = [" << qd_.transpose() << "]";
  report.ok = false;
  report.substeps = kMaxSubsteps;
  report.message = message.str();
  return report;
}

void CableSimulator::integrateCouplingRest() {
  if (!ends_.couplingIntegral() || dynamics_.model().heldTip()) return;
  const EndInputs ends = ends_.at(time_);
  // Anti-windup: a target beyond the cable's reach (the deployed length from the base) is one the tip can
  // never get to, and integrating that miss would grow the force without bound while the ROV stays there.
  // The shift holds until the target is back within reach.
  if (!ends.load_coupled || (ends.target_position - ends.base_position).norm() >= deployedLength()) return;
  ends_.integrateCouplingRest(dynamics_.data().tip_position - ends.target_position, dt_);
}

void CableSimulator::snapshot(SimulationSnapshot& out) {
  const int n = links();
  out.time = time_;
  out.q.resize(3 * n);
  out.qd.resize(3 * n);
  dynamics_.paperCoordinates(x_, out.q, out.qd);
  const EndInputs ends = ends_.at(time_);
  if (!dynamics_.evaluate(x_, ends, out.chain)) {
    throw std::runtime_error("snapshot: the state at t = " + std::to_string(time_) + " s is not valid");
  }
  out.axes.resize(3, n);
  out.twists.resize(n);
  for (int k = 0; k < n; ++k) {
    out.axes.col(k) = x_.segment<3>(StateLayout::axis(k)).normalized();
    out.twists(k) = x_(StateLayout::twist(k));
  }
  // The link frames at the links' stretched lengths, so that they sit on the ends above (sized after the
  // first snapshot: no allocation).
  levers_ = dynamics_.properties().length;
  if (out.chain.stretch.size() == n) levers_ += out.chain.stretch;
  linkFrames(out.axes, out.twists, out.chain.ends.col(0), levers_, out.link_frames, out.after_azimuth,
             out.after_elevation, alpha_hint_);
  if (!alpha_hint_.allFinite()) alpha_hint_.setZero();  // never let a bad hint outlive this instant
  out.dissipated_energy = x_(StateLayout::dissipated(n));
  out.work_input = x_(StateLayout::workInput(n));
  out.total_energy = out.chain.kinetic_energy + out.chain.potential_energy + out.chain.elastic_energy + out.chain.contact_energy +
                     out.dissipated_energy - out.work_input;
  out.first_link = firstLink();
  out.largest_tension = largest_tension_;
  out.snaps = snaps_;
  out.deployed_length = deployedLength();
  out.winch_speed = hasWinch() ? ends_.winch().motion().speed : 0.0;
  out.line_pull = out.chain.tension(out.first_link);
  // The bodies in the paper frame like the cable (the inputs' attitudes are the world frame's).
  out.vessel_attitude = worldToPaperAttitude(ends_.baseAttitude(time_));
  out.rov_attitude = worldToPaperAttitude(ends_.loadAttitude(time_));
  out.rov_velocity.setZero();
  out.rov_angular_velocity.setZero();
  out.rov_thrust = applied_thrust_;
  if (hasBody()) {  // from the evaluation above: the body's terms at x
    const RovBodyTerms& body = dynamics_.data().body;
    // Through the world frame's quaternion, so that the node's paperToWorldAttitude publishes it as it was
    // (the same sign: a quaternion from a rotation matrix has either).
    out.rov_attitude = worldToPaperAttitude(bodyPoseAttitude(body.rotation));
    out.rov_velocity = body.rotation * body.velocity.head<3>();
    out.rov_angular_velocity = body.omega;
  }
  out.vessel_origin = ends.base_position - out.vessel_attitude * params_.base.hang_off;
  out.rov_origin = (ends.load_coupled ? ends.target_position : Eigen::Vector3d(out.chain.ends.col(n))) -
                   out.rov_attitude * params_.load.attachment;
  out.vessel = wrenchAboutOrigin(out.chain.base_force, out.vessel_attitude, params_.base.hang_off);
  const Eigen::Vector3d on_rov =
      params_.load.mode == LoadMode::kAttached ? Eigen::Vector3d(-out.chain.coupling_force) : out.chain.load_force;
  out.rov = wrenchAboutOrigin(on_rov, out.rov_attitude, params_.load.attachment);
  // A clamped base holds the base link with a torque, and a clamped tip the last link: the vessel and
  // the ROV (or anchor) feel their opposites.
  const Eigen::Vector3d base_clamp = -dynamics_.data().clamp_torque;
  out.vessel.moment += base_clamp;
  out.vessel.moment_body += out.vessel_attitude.conjugate() * base_clamp;
  const Eigen::Vector3d tip_clamp = -dynamics_.data().tip_clamp_torque;
  out.rov.moment += tip_clamp;
  out.rov.moment_body += out.rov_attitude.conjugate() * tip_clamp;
  couplingPort(ends, out);
}

CouplingPort portInWorldAxes(const CouplingPort& paper) {
  CouplingPort world;
  world.point = paperToWorld(paper.point);
  world.velocity = paperToWorld(paper.velocity);
  world.force = paperToWorld(paper.force);
  world.moment = paperToWorld(paper.moment);
  world.stiffness = paperToWorldMap(paper.stiffness);
  world.damping = paperToWorldMap(paper.damping);
  return world;
}

void CableSimulator::couplingPort(const EndInputs& ends, SimulationSnapshot& out) const {
  CouplingPort& port = out.port;
  port = CouplingPort();
  if (params_.load.mode != LoadMode::kAttached) return;
  // The coupling force on the ROV is k (tip - point) + c (tip velocity - point velocity) at the present
  // tip state: its derivatives in the point's position and velocity are -k and -c on the diagonal.
  const LoadConstants& load = dynamics_.model().load();
  port.point = ends.target_position;
  port.velocity = ends.target_velocity;
  port.force = -out.chain.coupling_force;
  port.moment = -dynamics_.data().tip_clamp_torque;
  port.stiffness.topLeftCorner<3, 3>() = -load.coupling_stiffness * Eigen::Matrix3d::Identity();
  port.damping.topLeftCorner<3, 3>() = -load.coupling_damping * Eigen::Matrix3d::Identity();
}

void CableSimulator::setCurrent(const Eigen::Vector3d& current) {
  checkCurrent(current);
  dynamics_.current().setUniformWorld(current);
  start_balance_known_ = false;
  scheme_->forget();
}

void CableSimulator::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                   const Eigen::Quaterniond& attitude, double at) {
  checkPosition("load target position", position);
  checkVelocity("load target velocity", velocity);
  checkAttitude("load target attitude", attitude);
  ends_.setLoadTarget(position, velocity, attitude, std::isnan(at) ? time_ : at);
  start_balance_known_ = false;
  scheme_->forget();
}

void CableSimulator::setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                   const Eigen::Quaterniond& attitude) {
  checkPosition("base target position", position);
  checkVelocity("base target velocity", velocity);
  checkAttitude("base target attitude", attitude);
  ends_.setBaseTarget(position, velocity, attitude);
  start_balance_known_ = false;
  drift_reference_known_ = false;
  scheme_->forget();
}

}  // namespace cable_dynamics
