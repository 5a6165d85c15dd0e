#include "cable_dynamics/simulation/time_schemes/linear_implicit.h"

#include <cassert>
#include <cmath>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/power_balance.h"
#include "cable_dynamics/dynamics/link_rates.h"
#include "cable_dynamics/dynamics/rov_body.h"

namespace cable_dynamics {
namespace {

/// u turned by the rotation vector `turn` [rad] (Rodrigues), exactly a rotation at any angle:
/// u cos a + (t x u) sin(a)/a + t (t.u) (1 - cos a)/a^2 with t = turn, a = |t|. A step turns a link by
/// far less than 0.01 rad: there the series of the three coefficients, exact to round-off (the first
/// term left out is a^8/8! < 3e-21), spare the step two library calls per link and stage.
inline Eigen::Vector3d turned(const Eigen::Vector3d& u, const Eigen::Vector3d& turn) {
  const double a2 = turn.squaredNorm();
  double cosine, sine_over, versine_over;  // cos a, sin(a)/a, (1 - cos a)/a^2
  if (a2 < 1e-4) {
    cosine = 1.0 - a2 / 2.0 * (1.0 - a2 / 12.0 * (1.0 - a2 / 30.0));
    sine_over = 1.0 - a2 / 6.0 * (1.0 - a2 / 20.0 * (1.0 - a2 / 42.0));
    versine_over = 0.5 * (1.0 - a2 / 12.0 * (1.0 - a2 / 30.0 * (1.0 - a2 / 56.0)));
  } else {
    const double a = std::sqrt(a2);
    cosine = std::cos(a);
    sine_over = std::sin(a) / a;
    versine_over = (1.0 - cosine) / a2;
  }
  return cosine * u + sine_over * turn.cross(u) + (versine_over * turn.dot(u)) * turn;
}

/// The frame of a link (axis u, twist sigma) turned by the rotation vector phi [rad]: the axis exactly,
/// the twist by sigma' integrated along the turn with the midpoint rule at the bisector of the axis's
/// start and end (O(|phi|^2) from the turn's middle axis, so the twist's error stays O(|phi|^3)).
inline void turnFrame(Eigen::VectorXd& x, int k, const Eigen::Vector3d& phi) {
  const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k));
  const Eigen::Vector3d end = turned(axis, phi);
  x(StateLayout::twist(k)) += twistRate(phi, (axis + end).normalized());
  x.segment<3>(StateLayout::axis(k)) = end;
}

/// The stages' gamma for a spectral radius at infinity rho_inf in [0, 1]: R(inf) = 1 - 2/gamma +
/// 1/(2 gamma^2) = -rho_inf, i.e. (1 + rho) gamma^2 - 2 gamma + 1/2 = 0, the smaller root (the smaller
/// error constant): rho = 0 gives 1 - 1/sqrt(2), rho = 1 gives 1/2.
double gammaFor(double rho_infinity) {
  return (1.0 - std::sqrt(0.5 * (1.0 - rho_infinity))) / (1.0 + rho_infinity);
}

}  // namespace

LinearImplicitScheme::LinearImplicitScheme(int links, double rho_infinity, bool body, bool axial)
    : gamma_(gammaFor(rho_infinity)), solver_(links), body_(body), axial_(axial) {
  stage_.setZero(StateLayout::size(links, body, axial));
  for (Eigen::VectorXd* v : {&stretch_rate_, &stretch_spin1_, &stretch_turn1_, &stretch_rate2_, &stretch_scratch_, &stretch_zero_,
                             &stretch_shift_}) {
    v->setZero(axial ? links : 0);
  }
  for (Eigen::Matrix3Xd* m : {&omega_, &turn1_, &spin1_, &shift1_, &push1_, &rotation_, &translation_,
                              &contact_base_shift_, &contact_omega_shift_}) {
    m->setZero(3, links);
  }
}

LinearImplicitScheme::StagePower LinearImplicitScheme::stagePower(const ChainModel& model, const ChainData& data,
                                                                  const EndInputs& ends,
                                                                  const ContactVelocityShift& contact_shift,
                                                                  const Eigen::VectorXd& stretch_shift) const {
  // The powers at a stage's state, with its solved accelerations: drag, dampers and added mass taken out;
  // what the base, the coupling and a turning clamp put in. Affine in the accelerations, so the mean of
  // the two stages' is the step's to second order.
  const int n = model.links(), first = data.deployed.firstLink();
  double added_power = 0.0;
  for (int k = first; k < n; ++k) {
    const LinkConstants& c = data.deployed.of(k);
    const LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    const StiffLinkTerms& terms = solver_.link(k);
    Vec3 base_weight, axis_weight;
    linkAddedMassPowerWeights(c, i, block.u[i], block.axis_rate[i], block.base_vel[i], base_weight, axis_weight);
    const Vec3 axis_acc = toVec3(terms.angular_acc.cross(toEigen(block.u[i]))) + block.beta[i];
    added_power += dot(base_weight, block.known_acc[i] + toVec3(terms.delta_acc)) + dot(axis_weight, axis_acc);
  }
  const Eigen::Vector3d tip_acc = data.tip_known_acc + solver_.tipDelta();
  added_power -= (model.load().inertia - model.load().mass) * tip_acc.dot(data.tip_velocity);
  // The seabed's losses at the velocities the stage solved its dampers at, not at the stage's start
  // velocity (data.contact_dissipation): for a damper c on a mass m the stages then book what the step takes
  // out of the motion within 0.2 % at h c / m = 1 and 5 % at 5, where the start velocity books 22 % and 7.4
  // times too much (docs/MODEL.md section 6; test_implicit_contact_losses).
  const double contact = seabedContactDissipation(model, data, contact_shift);
  // The stretches' dampers likewise (an axial damper of 200 N s on 1 m links of 0.5 kg: h c / m = 4 at
  // 10 ms; booked at the start rates, a ringing elastic pendulum's balance was first order in h).
  const double axial = axial_ ? axialLossAtShiftedRates(model, data, stretch_shift) : 0.0;
  return {endsInputPower(model, data, ends, solver_.baseForce()), lossPower(model, data, added_power, contact, axial)};
}

bool LinearImplicitScheme::advance(ChainDynamics& f, const EndConditions& end_conditions, double t, double h,
                                   Eigen::VectorXd& x) {
  assert(x.size() == f.stateSize());
  if (!x.allFinite()) return false;
  const ChainModel& model = f.model();
  const ChainData& data = f.data();
  const int n = f.links(), first = data.deployed.firstLink();
  const double g = gamma_, gh = gamma_ * h;
  // The state is (phi, w): the links' rotation vectors from x_n's frames and their angular velocities;
  // the matrix of both stages is W = M + g h D + g^2 h^2 K (one recursion each), with K, D the Jacobians
  // of the generalized forces in the rotations and the velocities (stiff_articulated_body.h).
  //
  // Stage 1 at x_n: (I - g h A) k1 = h F(x_n) reads W a1 = G(x_n) - g h K w_n, with k1 = (kphi1, kw1),
  // kw1 = h a1, kphi1 = h (w_n + g kw1).
  const EndInputs start = end_conditions.at(t);
  f.computeLoads(x, start);
  if (axial_) solver_.linearizeStretches(model, data, h);  // for both stages
  // W may be any approximation (a W-method keeps its order whatever the Jacobian): stage 1 reuses the last
  // step's stage-2 terms, linearized O(h) away, and saves a linearization a step. Its geometric stiffness
  // is refreshed from the stage-2 solve's tensions, though: left at stage 1's (whose right-hand side
  // carries -g h K w_n), an undamped stiff tether in air gained energy and diverged at rho_inf = 1
  // (docs/MODEL.md section 6).
  if (!tensions_known_) {
    solver_.linearize(model, data, start, false);
  } else {
    solver_.geometricFromLastTension(model, data);
  }
  solver_.clearExtra();
  for (int k = first; k < n; ++k) {
    omega_.col(k) = x.segment<3>(StateLayout::omega(k));
    translation_.col(k) = data.links.get(&LinkBlock::base_vel, k);
  }
  const Eigen::Vector3d clamp_rate = data.clamp_omega;
  // The tip's rate for the stiffness on it: relative to the target when coupled (the coupling's spring),
  // its own velocity otherwise (the seabed's contact with the load).
  const Eigen::Vector3d tip_rate1 =
      start.load_coupled ? Eigen::Vector3d(data.tip_velocity - start.target_velocity) : data.tip_velocity;
  const Eigen::Vector3d tip_clamp_rate = data.tip_clamp_omega;
  solver_.addJacobianTimes(model, data, -gh, 0.0, omega_, clamp_rate, tip_clamp_rate, translation_, tip_rate1);
  if (axial_) {  // the stretches as the rotations: -g h K s'_n
    for (int k = 0; k < n; ++k) stretch_rate_(k) = x(StateLayout::stretchRate(n, body_, k));
    solver_.addStretchJacobianTimes(model, data, -gh, 0.0, stretch_rate_, stretch_zero_);
  }
  solver_.solve(model, data, gh, gh * gh);
  if (body_) finishRovBody(model.body(), data.tip_known_acc + solver_.tipDelta(), f.data().body);
  stage_ = x;
  if (body_) {  // as a link: kw1 = h a1, kphi1 = h (w_n + g kw1), in the body's frame
    const Eigen::Vector3d omega = x.segment<3>(StateLayout::bodyOmega(n));
    body_spin1_ = h * data.body.acceleration.tail<3>();
    body_turn1_ = h * (omega + g * body_spin1_);
    stage_.segment<4>(StateLayout::bodyAttitude(n)) = turnedAttitude(x.segment<4>(StateLayout::bodyAttitude(n)), body_turn1_);
    stage_.segment<3>(StateLayout::bodyOmega(n)) = omega + body_spin1_;
  }
  for (int k = first; k < n; ++k) {
    const StiffLinkTerms& terms = solver_.link(k);
    spin1_.col(k) = h * terms.angular_acc;  // kw1 [rad/s]
    push1_.col(k) = h * terms.delta_acc;    // the base end's velocity change [m/s]
    turn1_.col(k) = h * (omega_.col(k) + g * spin1_.col(k));  // kphi1 [rad]
    shift1_.col(k) = h * (translation_.col(k) + g * push1_.col(k));  // the base end's displacement [m]
    turnFrame(stage_, k, turn1_.col(k));
    stage_.segment<3>(StateLayout::omega(k)) = omega_.col(k) + spin1_.col(k);
  }
  if (axial_) {  // ks'1 = h s''_1, ks1 = h (s'_n + g ks'1)
    for (int k = first; k < n; ++k) {
      stretch_spin1_(k) = h * solver_.link(k).stretch_acc;
      stretch_turn1_(k) = h * (stretch_rate_(k) + g * stretch_spin1_(k));
      stage_(StateLayout::stretch(n, body_, k)) += stretch_turn1_(k);
      stage_(StateLayout::stretchRate(n, body_, k)) += stretch_spin1_(k);
      stretch_shift_(k) = g * stretch_spin1_(k);  // stage 1 solved the dampers at s'_n + g ks'1
    }
  }
  const Eigen::Vector3d tip_push1 = h * solver_.tipDelta();
  const Eigen::Vector3d tip_shift1 = h * tip_rate1 + g * h * tip_push1;
  // Stage 1 takes its dampers at v_n + g kw1 (W a1 = G(x_n) - g h D a1); only the seabed's read it.
  const bool seabed = model.seabedContact().enabled();
  if (seabed) {
    contact_base_shift_ = g * push1_;
    contact_omega_shift_ = g * spin1_;
  }
  const StagePower power1 =
      stagePower(model, data, start, ContactVelocityShift{&contact_base_shift_, &contact_omega_shift_, g * tip_push1},
                 stretch_shift_);
  if (!stage_.allFinite()) return false;
  // Stage 2 at x_n + k1 (time t + h), written for k~2 = k2 + 2 k1 so that no mass-matrix product appears:
  // (I - g h A) k~2 = h F(x_n + k1) - 2 g h A k1, i.e. W a2 = G(x_n + k1) + g K (2 kphi1 - rphi2) + 2 g D kw1,
  // with rphi2 = h dexp^-1(kphi1) w_1 - 2 g h kw1, kw~2 = h a2, kphi~2 = rphi2 + g h kw~2.
  // The step: x_{n+1} = x_n + (k1 + k~2) / 2.
  const EndInputs end = end_conditions.at(t + h);
  f.computeLoads(stage_, end);
  solver_.linearize(model, data, end, true);  // stage 1's tensions
  tensions_known_ = true;
  solver_.clearExtra();
  for (int k = first; k < n; ++k) {
    const Eigen::Vector3d w1 = stage_.segment<3>(StateLayout::omega(k));
    const Eigen::Vector3d turn = turn1_.col(k);
    // dexp^-1 to first order (the next term is O(h^2) in it): the rate of phi is w - phi x w / 2.
    const Eigen::Vector3d rate = h * (w1 - 0.5 * turn.cross(w1)) - 2.0 * g * h * spin1_.col(k);
    omega_.col(k) = rate;  // rphi2, kept for the update
    rotation_.col(k) = 2.0 * turn - rate;
    const Eigen::Vector3d rate_base = h * data.links.get(&LinkBlock::base_vel, k) - 2.0 * g * h * push1_.col(k);
    translation_.col(k) = 2.0 * shift1_.col(k) - rate_base;
  }
  const Eigen::Vector3d clamp2 = 2.0 * h * clamp_rate - h * data.clamp_omega;
  const Eigen::Vector3d tip_clamp2 = 2.0 * h * tip_clamp_rate - h * data.tip_clamp_omega;
  const Eigen::Vector3d tip_rate2 =
      h * (end.load_coupled ? Eigen::Vector3d(data.tip_velocity - end.target_velocity) : data.tip_velocity) -
      2.0 * g * h * tip_push1;
  solver_.addJacobianTimes(model, data, g, 0.0, rotation_, clamp2, tip_clamp2, translation_, 2.0 * tip_shift1 - tip_rate2);
  solver_.addJacobianTimes(model, data, 0.0, 2.0 * g, spin1_, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), push1_,
                           tip_push1);
  if (axial_) {  // as the rotations: r2 = h s'_1 - 2 g h ks'1; g K (2 ks1 - r2) + 2 g D ks'1
    for (int k = first; k < n; ++k) {
      stretch_rate2_(k) = h * stage_(StateLayout::stretchRate(n, body_, k)) - 2.0 * g * h * stretch_spin1_(k);
      stretch_scratch_(k) = 2.0 * stretch_turn1_(k) - stretch_rate2_(k);
    }
    solver_.addStretchJacobianTimes(model, data, g, 0.0, stretch_scratch_, stretch_zero_);
    solver_.addStretchJacobianTimes(model, data, 0.0, 2.0 * g, stretch_zero_, stretch_spin1_);
  }
  solver_.solve(model, data, gh, gh * gh);
  if (body_) finishRovBody(model.body(), data.tip_known_acc + solver_.tipDelta(), f.data().body);
  // Stage 2 takes its dampers at v_1 - 2 g kw1 + g kw~2 (W a2 = G(x_n + k1) + 2 g D kw1 - g h D a2).
  for (int k = first; seabed && k < n; ++k) {
    contact_base_shift_.col(k) = g * (h * solver_.link(k).delta_acc - 2.0 * push1_.col(k));
    contact_omega_shift_.col(k) = g * (h * solver_.link(k).angular_acc - 2.0 * spin1_.col(k));
  }
  for (int k = first; axial_ && k < n; ++k) {  // and stage 2 at s'_1 - 2 g ks'1 + g ks~'2
    stretch_shift_(k) = g * (h * solver_.link(k).stretch_acc - 2.0 * stretch_spin1_(k));
  }
  StagePower power2 = stagePower(
      model, data, end,
      ContactVelocityShift{&contact_base_shift_, &contact_omega_shift_, g * (h * solver_.tipDelta() - 2.0 * tip_push1)},
      stretch_shift_);
  if (end.load_coupled) {
    // The coupling's power F.v at x_n + k1 is O(h^2) from the step's end, x_n + (k1 + k~2)/2, and with a
    // stiff coupling damper (c / m_tip of hundreds per second) that error, summed over a run, showed as
    // energy put in (the TMS tether at 10 ms: 3.2e-3 of the scale). Moved to the end to first order in
    // the difference (dx, dv of the tip: (k~2 - k1)/2), F = -k_c (x - x_t) - c_c (v - v_t) being linear:
    // P_end = F.v + F.dv - (k_c dx + c_c dv).v.
    const Eigen::Vector3d tip_push2 = h * solver_.tipDelta();
    const Eigen::Vector3d dv = 0.5 * (tip_push2 - tip_push1);
    const Eigen::Vector3d dx = 0.5 * (tip_rate2 + gh * tip_push2 - tip_shift1);
    power2.input += model.load().coupling().powerShift(data.coupling, data.tip_velocity, dx, dv);
  }
  for (int k = first; k < n; ++k) {
    const Eigen::Vector3d spin2 = h * solver_.link(k).angular_acc;
    const Eigen::Vector3d turn2 = omega_.col(k) + gh * spin2;
    const Eigen::Vector3d omega = x.segment<3>(StateLayout::omega(k));
    turnFrame(x, k, 0.5 * (turn1_.col(k) + turn2));
    x.segment<3>(StateLayout::omega(k)) = omega + 0.5 * (spin1_.col(k) + spin2);
  }
  if (body_) {  // rphi2 = h dexp^-1(kphi1) w_1 - 2 g h kw1, kphi~2 = rphi2 + g h kw~2, as the links'
    const Eigen::Vector3d w1 = stage_.segment<3>(StateLayout::bodyOmega(n));
    const Eigen::Vector3d spin2 = h * data.body.acceleration.tail<3>();
    const Eigen::Vector3d turn2 = h * (w1 - 0.5 * body_turn1_.cross(w1)) - 2.0 * g * h * body_spin1_ + gh * spin2;
    x.segment<4>(StateLayout::bodyAttitude(n)) =
        turnedAttitude(x.segment<4>(StateLayout::bodyAttitude(n)), 0.5 * (body_turn1_ + turn2));
    x.segment<3>(StateLayout::bodyOmega(n)) += 0.5 * (body_spin1_ + spin2);
  }
  if (axial_) {  // x_{n+1} = x_n + (k1 + k~2) / 2, with ks'2 = h s''_2 and k~s2 = r2 + g h ks'2
    for (int k = first; k < n; ++k) {
      const double spin2 = h * solver_.link(k).stretch_acc;
      x(StateLayout::stretch(n, body_, k)) += 0.5 * (stretch_turn1_(k) + stretch_rate2_(k) + gh * spin2);
      x(StateLayout::stretchRate(n, body_, k)) += 0.5 * (stretch_spin1_(k) + spin2);
    }
  }
  // The power balance: inputs into work_input, losses into dissipated, each the stages' mean.
  x(StateLayout::workInput(n)) += 0.5 * h * (power1.input + power2.input);
  x(StateLayout::dissipated(n)) -= 0.5 * h * (power1.dissipative + power2.dissipative);
  return x.allFinite();
}

}  // namespace cable_dynamics
