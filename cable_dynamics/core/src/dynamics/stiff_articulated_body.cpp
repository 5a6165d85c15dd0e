/// \file
/// \brief The articulated-body recursion with effective-inertia terms (stiff_articulated_body.h).
///
/// Unknowns per link: its angular acceleration alpha_k and d_k, its base end's acceleration less the
/// known part a0_k (as in articulated_body.cpp: a_k = a0_k + d_k, d_{k+1} = d_k + l_k alpha_k x u_k).
/// Spatial quantities are (rotation; translation) pairs at a link's base end in world axes: the link's
/// Newton-Euler equations about its base end read I_k (alpha_k; d_k) + p_k = W_k - X^T W_{k+1}, with I_k
/// its spatial inertia (plus the drag's damping and the geometric stiffness, weighted), p_k the bias
/// (velocity terms, known accelerations, minus the loads), W_k the wrench joint k passes to it and X^T the
/// shift of a wrench at the far end to the base end (torque + l u x force). Joint k passes the force
/// rigidly and the torque -Z_k nu_k, nu_k = alpha_k - alpha_{k-1}, Z_k = c_D D_j + c_K K_j.
///
/// Backward (tip to base): the outboard part's articulated inertia at joint k, I^A = I_k + X^T I^a X, and
/// bias p^A; with D = I^A_rr + Z, the joint's motion nu = -D^-1 (U^T X a_parent + p^A_r) (U: I^A's
/// rotation columns), and the parent sees I^a = I^A - U D^-1 U^T, p^a = p^A - U D^-1 p^A_r. Forward
/// (base to tip): alpha_k = alpha_{k-1} + nu_k, d_k from the parent's far end.
///
/// With the loads' passes, this is the implicit step's hot path (twice a step): no heap allocation, and
/// measure any change with bench/ (stiff_step).
#include "cable_dynamics/dynamics/stiff_articulated_body.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/joint_springs.h"
#include "cable_dynamics/dynamics/forces/point_drag.h"
#include "cable_dynamics/dynamics/forces/tip_clamp.h"
#include "cable_dynamics/dynamics/hot_path.h"
#include "cable_dynamics/dynamics/kinematics.h"
#include "cable_dynamics/dynamics/link_rates.h"
#include "cable_dynamics/dynamics/seabed_contact.h"

// Inline every Eigen call of the two hot functions: without it GCC calls the 3x3 products out of line
// (and in the default architecture's code from the AVX2 and AVX-512 copies).
#if defined(__GNUC__) && !defined(__clang__)
#define CABLE_FLATTEN __attribute__((flatten))
#else
#define CABLE_FLATTEN
#endif

namespace cable_dynamics {
namespace {

inline Eigen::Matrix3d symmetrized(const Eigen::Matrix3d& m) { return 0.5 * (m + m.transpose()); }

}  // namespace

StiffArticulatedBody::StiffArticulatedBody(int links) : links_(links), contact_(links) {}

CABLE_HOT_PATH CABLE_FLATTEN void StiffArticulatedBody::linearize(const ChainModel& model, const ChainData& data, const EndInputs& ends,
                                     bool use_last_tension) {
  const int n = model.links(), first = data.deployed.firstLink();
  const LinkProperties& p = data.deployed.properties();
  const bool bending = model.stiffnessModel() == StiffnessModel::kBending;
  const bool in_water = model.fluidDensity() > 0.0;
  const LinkBlocks& blocks = data.links;
  const SeabedContactConstants& contact = model.seabedContact();
  for (int k = first; k < n; ++k) {
    StiffLinkTerms& t = links_[k];
    const Eigen::Vector3d u = blocks.get(&LinkBlock::u, k);
    t.axis = u;
    t.far_damping = 0.0;
    // Joint k: bend across its mean axis, twist about it (the paper model's springs are not handled
    // here: the simulator refuses them with this integrator).
    if (bending) {
      const Eigen::Vector3d prev = k > first ? blocks.get(&LinkBlock::u, k - 1) : data.clamp_axis;
      const Eigen::Vector3d mean = meanAxis(prev, u, u);
      // A joint folded onto its neighbour adds its fold stop's tangent across (forces/fold_stop.h).
      double across = p.stiffness_elevation(k);
      const double cosine = prev.dot(u);
      if (k > first && cosine < 0.0) {
        across += model.foldStop(p, k).tangent(std::atan2(prev.cross(u).norm(), cosine));
      }
      t.joint_stiffness = jointBlock(across, p.stiffness_torsion(k), mean);
      t.joint_damping = jointBlock(p.damping_elevation(k), p.damping_torsion(k), mean);
    }
    // Drag: its damping over (omega, v_base), with the current at the link's middle (LinkDrag::damping).
    if (in_water) {
      const double l = data.deployed.get(&LinkConstants::length, k);
      const Eigen::Vector3d base = blocks.get(&LinkBlock::base_pos, k), v0 = blocks.get(&LinkBlock::base_vel, k);
      const Eigen::Vector3d relative = data.current.at(base.z() + 0.5 * l * u.z()) - v0;
      model.drag().damping(l, data.deployed.dragCoefficients(k), u, relative, blocks.get(&LinkBlock::axis_rate, k), t.drag_rr,
                           t.drag_rv, t.drag_vv);
      // The far half's skin friction f = c |w| w along u, with w the flow past the far-end point along u
      // (external_loads.cpp, at this state): 2 c |w| = 2 sqrt(c |f|) per unit of the point's velocity.
      const double far_tangential = data.deployed.get(&LinkConstants::far_tangential, k);
      t.far_damping = 2.0 * std::sqrt(far_tangential * std::abs(blocks.get(&LinkBlock::far_drag, k)));
    } else if (contact.enabled()) {
      t.drag_rr.setZero();  // the seabed's damping adds to them below
      t.drag_rv.setZero();
      t.drag_vv.setZero();
    }
    if (contact.enabled()) linearizeContact(model, data, k, t, contact_[k]);
    t.lever = data.deployed.get(&LinkConstants::length, k) + blocks.get(&LinkBlock::stretch, k);
  }
  // Geometric stiffness: the moment of everything outboard about link k's base end, u x G with
  // G = l F_outboard + (the link's own first moment), turns with the link: dtau = -(G.u) P dtheta - ...;
  // the symmetric, restoring part (G.u) P is kept, in tension only. With the joint forces of a solve,
  // G.u = l (T_k + T_{k+1}) / 2, the mean tension along the link times its length.
  if (use_last_tension) geometricFromLastTension(model, data);
  Eigen::Vector3d outboard = data.load_external;
  for (int k = n - 1; k >= first && !use_last_tension; --k) {
    StiffLinkTerms& t = links_[k];
    const Eigen::Vector3d u = blocks.get(&LinkBlock::u, k);
    // The far-end point's weight and skin friction (axial elasticity).
    outboard.z() += data.deployed.get(&LinkConstants::far_weight, k);
    outboard += blocks.get(&LinkBlock::far_drag, k) * u;
    const Eigen::Vector3d g = t.lever * outboard + blocks.get(&LinkBlock::moment, k);
    t.geometric = std::max(0.0, g.dot(u));
    outboard += blocks.get(&LinkBlock::force, k);
  }
  // The load: its drag 1/2 rho C_d A |v| v has the damping 1/2 rho C_d A (|v| I + v v^T / |v|).
  const LoadConstants& load = model.load();
  load_drag_.setZero();
  if (in_water && load.drag_area > 0.0) {
    load_drag_ = pointDragDamping(model.fluidDensity(), load.drag_area, data.tip_velocity,
                                  data.current.at(data.tip_position.z()));
  }
  // A clamped tip (joint_torques.cpp): bend only, across the mean of the last axis and the clamp's.
  if (model.tipClamp().active()) {
    model.tipClamp().jacobian(blocks.get(&LinkBlock::u, n - 1), data.tip_clamp_axis, tip_clamp_stiffness_, tip_clamp_damping_);
  }
  load_contact_stiffness_.setZero();
  load_contact_damping_.setZero();
  ContactPlace place;
  if (contact.load_contact && contactPlace(contact.bed, toVec3(data.tip_position), {0.0, 0.0, 0.0}, place)) {
    place.offset = data.anchors.loadOffset(data.tip_position);
    contactJacobian(contact.loadLaw(), place, data.tip_velocity, load_contact_stiffness_, load_contact_damping_);
  }
  coupling_stiffness_ = ends.load_coupled ? load.coupling().stiffnessJacobian() : 0.0;
  coupling_damping_ = ends.load_coupled ? load.coupling().dampingJacobian() : 0.0;
}

void StiffArticulatedBody::linearizeContact(const ChainModel& model, const ChainData& data, int k, StiffLinkTerms& t,
                                            StiffContactTerms& out) {
  // The points' stiffness K(s) and damping D(s) summed as K_m = sum s^m K(s) (and D_m), then laid out over
  // (rotation, base end) as the drag's: [[-[u]x K2 [u]x, [u]x K1], [-K1 [u]x, K0]].
  const SeabedContactConstants& c = model.seabedContact();
  const double l = data.deployed.get(&LinkConstants::length, k);
  t.in_contact = false;
  out = StiffContactTerms();
  if (l <= 0.0) return;
  const Eigen::Vector3d base = data.links.get(&LinkBlock::base_pos, k), u = data.links.get(&LinkBlock::u, k);
  if (std::max(base.z(), base.z() + l * u.z()) <= c.bed.shallowest()) return;  // all above the bed
  const Eigen::Vector3d velocity = data.links.get(&LinkBlock::base_vel, k), rate = data.links.get(&LinkBlock::axis_rate, k);
  const ContactLaw law = c.linkLaw(k, l / c.points);
  Eigen::Matrix3d k_m[3] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  Eigen::Matrix3d d_m[3] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  if (c.bed.flat()) {
    // The points share the normal and the axis's direction along the bed, so the friction's pattern: sum
    // the Jacobian's three scalars per power of s (forces/contact.h, contactJacobianParts) and assemble
    // once. A quarter of a chain's implicit step went to the per-point 3x3 products (MoorDyn's WD0050
    // heaving 5 m, perf).
    ContactPlace place;  // its normal: +z
    place.has_along = alongTheBed(toVec3(u), place.normal, place.along);
    double spring[3] = {0.0, 0.0, 0.0}, damper[3] = {0.0, 0.0, 0.0}, secant[3] = {0.0, 0.0, 0.0};
    const double depth = c.bed.shallowest();
    const double* anchors = data.anchors.of(k);
    for (int j = 0; j < c.points; ++j) {
      const double s = c.node[j] * l;
      place.delta = base.z() + s * u.z() - depth;
      if (place.delta <= 0.0) continue;
      if (anchors) place.offset = ContactAnchors::offset(anchors, j, toVec3(Eigen::Vector3d(base + s * u)));
      const ContactJacobianParts parts = contactJacobianParts(law, place, toVec3(Eigen::Vector3d(velocity + s * rate)));
      t.in_contact = true;
      double power = 1.0;
      for (int m = 0; m < 3; ++m) {
        spring[m] += power * parts.normal_stiffness;
        damper[m] += power * parts.normal_damping;
        secant[m] += power * parts.friction_secant;
        power *= s;
      }
    }
    if (!t.in_contact) return;
    const Eigen::Matrix3d pattern = frictionPattern(law, place);
    const double over_breakout = law.friction_breakout > 0.0 ? 1.0 / law.friction_breakout : 0.0;
    for (int m = 0; m < 3; ++m) {
      k_m[m] = (secant[m] * over_breakout) * pattern;
      k_m[m](2, 2) += spring[m];
      d_m[m] = (secant[m] / law.friction_velocity) * pattern;
      d_m[m](2, 2) += damper[m];
    }
  } else {
    Eigen::Matrix3d stiffness, damper;
    for (int j = 0; j < c.points; ++j) {
      const double s = c.node[j] * l;
      ContactPlace place;
      const Eigen::Vector3d point = base + s * u;
      if (!contactPlace(c.bed, toVec3(point), toVec3(u), place)) continue;
      if (const double* anchors = data.anchors.of(k)) place.offset = ContactAnchors::offset(anchors, j, toVec3(point));
      contactJacobian(law, place, velocity + s * rate, stiffness, damper);
      t.in_contact = true;
      double power = 1.0;
      for (int m = 0; m < 3; ++m) {
        k_m[m] += power * stiffness;
        d_m[m] += power * damper;
        power *= s;
      }
    }
    if (!t.in_contact) return;
  }
  const Eigen::Matrix3d x = skew(u);
  out.rr = -x * k_m[2] * x;
  out.rv = x * k_m[1];
  out.vv = k_m[0];
  t.drag_rr -= x * d_m[2] * x;
  t.drag_rv += x * d_m[1];
  t.drag_vv += d_m[0];
}

void StiffArticulatedBody::geometricFromLastTension(const ChainModel& model, const ChainData& data) {
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    const double far = k + 1 < model.links() ? links_[k + 1].tension : tip_tension_;
    links_[k].geometric = std::max(0.0, 0.5 * links_[k].lever * (links_[k].tension + far));
  }
}

void StiffArticulatedBody::clearExtra() {
  for (StiffLinkTerms& t : links_) {
    t.extra_torque.setZero();
    t.extra_force.setZero();
    t.stretch_extra = 0.0;
    t.far_extra.setZero();
  }
  load_extra_.setZero();
}

void StiffArticulatedBody::linearizeStretches(const ChainModel& model, const ChainData& data, double horizon) {
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    StiffLinkTerms& t = links_[k];
    // The stretch's law (forces/axial_spring.h): its k and c unless the link stays clearly slack over the
    // step's horizon (s + h s' below -0.1 % of its length, the snap counter's margin); 0 there. With the
    // law's own derivatives (0 while slack) a link snapping taut within a step, or a light link ringing
    // about s = 0 after a snap, was an explicit step at h omega of hundreds for its stiff spring, and
    // diverged; with k everywhere (a W-method keeps its order with any matrix, but not its accuracy at
    // h omega = 300) a falling mass was braked by a spring not yet there: the snap's peak came 14 % low
    // (the snap test at 10 ms).
    const int lane = LinkBlocks::lane(k);
    const LinkBlock& block = data.links.of(k);
    const LinkConstants& constants = data.deployed.of(k);
    const double s = block.stretch[lane], rate = block.stretch_rate[lane];
    const double l = constants.length[lane];
    const bool taut = s + std::max(0.0, horizon * rate) > -kClearlySlack * l;
    // The same for the slack stop: in the matrix where the link is past it or comes within 0.1 % of its
    // length of it over the horizon.
    const bool stopped = AxialSpring::pastStop(s + std::min(0.0, horizon * rate), l) < kClearlySlack * l;
    t.stretch_spring = taut || stopped ? constants.axial_stiffness[lane] : 0.0;
    t.stretch_damper = taut || stopped ? constants.axial_damping[lane] : 0.0;
  }
}

void StiffArticulatedBody::addStretchJacobianTimes(const ChainModel& model, const ChainData& data, double stiffness_factor, double damping_factor,
                                                   const Eigen::VectorXd& stretch, const Eigen::VectorXd& rate) {
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    StiffLinkTerms& t = links_[k];
    t.stretch_extra += stiffness_factor * t.stretch_spring * stretch(k) + damping_factor * t.stretch_damper * rate(k);
  }
}

CABLE_HOT_PATH void StiffArticulatedBody::addJacobianTimes(const ChainModel& model, const ChainData& data, double stiffness_factor, double damping_factor,
                                            const Eigen::Matrix3Xd& rotation, const Eigen::Vector3d& base_rotation,
                                            const Eigen::Vector3d& tip_rotation, const Eigen::Matrix3Xd& translation,
                                            const Eigen::Vector3d& tip_translation) {
  const int n = model.links(), first = data.deployed.firstLink();
  for (int k = first; k < n; ++k) {
    StiffLinkTerms& t = links_[k];
    const Eigen::Vector3d r = rotation.col(k);
    const Eigen::Vector3d relative = r - (k > first ? Eigen::Vector3d(rotation.col(k - 1)) : base_rotation);
    // Joint k: g(theta + dtheta) = g - K dtheta puts -K_j (dtheta_k - dtheta_{k-1}) on link k and the
    // opposite on link k-1; "K r" is minus that.
    const Eigen::Vector3d joint =
        stiffness_factor * (t.joint_stiffness * relative) + damping_factor * (t.joint_damping * relative);
    t.extra_torque += joint;
    if (k > first) links_[k - 1].extra_torque -= joint;
    // The link's geometric stiffness (on the rotation across it) and drag damping.
    const Eigen::Vector3d v = translation.col(k);
    t.extra_torque += damping_factor * (t.drag_rr * r + t.drag_rv * v);
    t.extra_force += damping_factor * (t.drag_rv.transpose() * r + t.drag_vv * v);
    t.extra_torque += (stiffness_factor * t.geometric) * (r - r.dot(t.axis) * t.axis);  // (G.u) P r
    if (t.far_damping > 0.0) {  // the far-end point moves as joint k + 1 (or the tip) does
      const Eigen::Vector3d far = k + 1 < n ? Eigen::Vector3d(translation.col(k + 1)) : tip_translation;
      t.far_extra += (damping_factor * t.far_damping * t.axis.dot(far)) * t.axis;
    }
    if (t.in_contact) {
      const StiffContactTerms& c = contact_[k];
      t.extra_torque += stiffness_factor * (c.rr * r + c.rv * v);
      t.extra_force += stiffness_factor * (c.rv.transpose() * r + c.vv * v);
    }
  }
  // The tip clamp: its spring on the last link's rotation relative to the clamp, -K (r - r_clamp).
  const Eigen::Vector3d tip_relative = rotation.col(n - 1) - tip_rotation;
  links_[n - 1].extra_torque +=
      stiffness_factor * (tip_clamp_stiffness_ * tip_relative) + damping_factor * (tip_clamp_damping_ * tip_relative);
  load_extra_ += (stiffness_factor * coupling_stiffness_ + damping_factor * coupling_damping_) * tip_translation +
                 damping_factor * (load_drag_ * tip_translation) +
                 stiffness_factor * (load_contact_stiffness_ * tip_translation) +
                 damping_factor * (load_contact_damping_ * tip_translation);
}

CABLE_HOT_PATH CABLE_FLATTEN void StiffArticulatedBody::solve(const ChainModel& model, const ChainData& data, double damping_weight,
                                 double stiffness_weight) {
  const int n = model.links(), first = data.deployed.firstLink();
  const LinkBlocks& blocks = data.links;
  const LoadConstants& load = model.load();
  const double cd = damping_weight, ck = stiffness_weight;
  const bool axial = model.axial();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // The load, a point at the tip: no rotational inertia, its mass plus the weighted drag and coupling.
  Eigen::Matrix3d child_rr = Eigen::Matrix3d::Zero(), child_rv = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d load_mass = (load.inertia + cd * coupling_damping_ + ck * coupling_stiffness_) * identity +
                              cd * (load_drag_ + load_contact_damping_) + ck * load_contact_stiffness_;
  Eigen::Vector3d tip_bias = load.inertia * data.tip_known_acc - data.load_external - load_extra_;
  if (model.body().active) {  // an ROV body on a ball joint: its 3x3 mass and bias at the tip (rov_body.h)
    load_mass += data.body.tip_mass;
    tip_bias += data.body.tip_mass * data.tip_known_acc + data.body.tip_bias;
  }
  Eigen::Matrix3d child_vv = load_mass;
  Eigen::Vector3d child_pr = Eigen::Vector3d::Zero();
  Eigen::Vector3d child_pv = tip_bias;
  for (int k = n - 1; k >= first; --k) {
    StiffLinkTerms& t = links_[k];
    const LinkConstants& c = data.deployed.of(k);
    const LinkBlock& block = blocks.of(k);
    const int i = LinkBlocks::lane(k);
    const double l = c.length[i];
    const Eigen::Vector3d u = toEigen(block.u[i]);
    if (axial) {
      // The far-end point (LinkConstants::far_mass), outboard of the stretch and inboard of joint k + 1:
      // its mass and its bias at the far end's known acceleration (articulated_body.cpp, farPointPass).
      const double far_mass = c.far_mass[i];
      const Vec3 far_acc = farEndKnownAcceleration(block.known_acc[i], block.beta[i], block.axis_rate[i],
                                                   l + block.stretch[i], block.stretch_rate[i]);
      t.far_bias = far_mass * toEigen(far_acc) - c.far_weight[i] * Eigen::Vector3d::UnitZ() - block.far_drag[i] * u -
                   t.far_extra;
      child_vv.diagonal().array() += far_mass;
      child_vv += (cd * t.far_damping) * (u * u.transpose());
      child_pv += t.far_bias;
    }
    if (axial && !model.stretchLocked(k)) {
      // The prismatic joint at the far end (axial elasticity): the outboard part passes along u the
      // stretch's tension and its impedance, u . J_v = -(T - extra) - (cd c + ck k) s'', so s'' =
      // -(U_v . d_far + U_r . alpha + u . p_v + T - extra) / D with U_r = rv u, U_v = vv u, D = u^T vv u +
      // cd c + ck k, which leaves I - U U^T / D and p - U (u . p_v + T - extra) / D at the rigid far end.
      t.stretch_rot = child_rv * u;
      t.stretch_lin = child_vv * u;
      t.stretch_inverse = 1.0 / (u.dot(t.stretch_lin) + cd * t.stretch_damper + ck * t.stretch_spring);
      t.stretch_bias = u.dot(child_pv) + block.axial_tension[i] - t.stretch_extra;
      const Eigen::Vector3d r = t.stretch_inverse * t.stretch_rot, v = t.stretch_inverse * t.stretch_lin;
      // Rank-one updates in place (symmetric up to rounding in rr and vv: the next symmetrized() takes it).
      child_rr.noalias() -= r * t.stretch_rot.transpose();
      child_rv.noalias() -= r * t.stretch_lin.transpose();
      child_vv.noalias() -= v * t.stretch_lin.transpose();
      child_pr -= t.stretch_bias * r;
      child_pv -= t.stretch_bias * v;
    } else {
      t.stretch_inverse = 0.0;  // rigid links, or a locked last stretch
      t.stretch_rot.setZero();
      t.stretch_lin.setZero();
      t.stretch_bias = 0.0;
    }
    const double lever = axial ? t.lever : l;  // base end to far end
    // The outboard part's inertia and bias moved from the far end to the base end: with R = l [u]x,
    // rr' = rr - rv R + R rv^T - R vv R (R rv^T = -(rv R)^T), rv' = rv + R vv, torque' = torque + R force.
    const Eigen::Matrix3d R = lever * skew(u);
    const Eigen::Matrix3d r_vv = R * child_vv;
    const Eigen::Matrix3d rv_r = child_rv * R;
    Eigen::Matrix3d a_rr = child_rr - rv_r - rv_r.transpose() - r_vv * R;
    Eigen::Matrix3d a_rv = child_rv + r_vv;
    Eigen::Matrix3d a_vv = child_vv;
    Eigen::Vector3d a_pr = child_pr + R * child_pv;
    Eigen::Vector3d a_pv = child_pv;
    // The link's own spatial inertia about its base end: rotation (c1 P + I_P u u^T), coupling h [u]x,
    // translation l A; plus the drag's damping and the geometric stiffness, weighted.
    const Eigen::Matrix3d uu = u * u.transpose(), P = identity - uu;
    const double la = l * c.added[i];
    Eigen::Matrix3d own_rv = c.half_moment[i] * skew(u) + cd * t.drag_rv;
    t.own_vv = c.translational[i] * identity - la * uu + cd * t.drag_vv;
    if (t.in_contact) {
      const StiffContactTerms& contact = contact_[k];
      own_rv += ck * contact.rv;
      t.own_vv += ck * contact.vv;
      a_rr += ck * contact.rr;
    }
    t.own_vr = own_rv.transpose();
    a_rr += (c.own_transverse[i] + ck * t.geometric) * P + c.polar[i] * uu + cd * t.drag_rr;
    if (k == n - 1) a_rr += ck * tip_clamp_stiffness_ + cd * tip_clamp_damping_;  // zero unless clamped
    a_rv += own_rv;
    a_vv += t.own_vv;
    // Its bias, as the ordinary recursion has it (articulated_body.cpp, linkTermsPass), less the extra
    // right-hand side.
    const Eigen::Vector3d known = toEigen(block.known_acc[i]), beta = toEigen(block.beta[i]);
    const Eigen::Vector3d omega = toEigen(block.omega[i]), rate = toEigen(block.axis_rate[i]);
    const Eigen::Vector3d mean = l * known + (0.5 * l * l) * beta;
    const Eigen::Vector3d own_force = c.translational[i] * known + c.half_moment[i] * beta -
                                      (c.added[i] * u.dot(mean)) * u - toEigen(block.force[i]);
    const Eigen::Vector3d own_moment = c.half_moment[i] * known + c.third_moment[i] * beta - toEigen(block.moment[i]);
    const double gyroscopic = c.polar[i] - c.thick_transverse[i];
    a_pr += u.cross(own_moment) + (gyroscopic * u.dot(omega)) * rate - toEigen(block.torque[i]) - t.extra_torque;
    t.own_bias = own_force - t.extra_force;
    a_pv += t.own_bias;
    // Joint k: D = I^A_rr + Z.
    const Eigen::Matrix3d joint = symmetrized(a_rr) + cd * t.joint_damping + ck * t.joint_stiffness;
    const Eigen::Matrix3d inverse = joint.inverse();
    t.forward_rot = inverse * a_rr;
    t.forward_lin = inverse * a_rv;
    t.nu_bias = inverse * a_pr;
    if (k == first) {
      // Force rows of the wrench at the base: J = rv^T nu + p_v (d = 0 at the base).
      base_force_ = a_pv;  // completed after the forward pass
      child_rv = a_rv;     // keep for the base force
      child_pv = a_pv;
      break;
    }
    child_rr = symmetrized(a_rr - a_rr * t.forward_rot);
    child_rv = a_rv - a_rr * t.forward_lin;
    child_vv = symmetrized(a_vv - a_rv.transpose() * t.forward_lin);
    child_pr = a_pr - a_rr * t.nu_bias;
    child_pv = a_pv - a_rv.transpose() * t.nu_bias;
  }
  // Forward: the base's clamp is at rest in this linearization (alpha = nu at the base link, d = 0).
  Eigen::Vector3d alpha = Eigen::Vector3d::Zero(), d = Eigen::Vector3d::Zero();
  for (int k = first; k < n; ++k) {
    StiffLinkTerms& t = links_[k];
    const Eigen::Vector3d nu = -(t.forward_rot * alpha + t.forward_lin * d) - t.nu_bias;
    alpha += nu;
    t.angular_acc = alpha;
    t.delta_acc = d;
    if (k == first) base_force_ = child_rv.transpose() * nu + child_pv;
    const Eigen::Vector3d u = blocks.get(&LinkBlock::u, k);
    d -= (axial ? t.lever : data.deployed.get(&LinkConstants::length, k)) * u.cross(alpha);  // the far end: + l alpha x u
    if (axial) {  // and its stretch (zero when locked: stretch_inverse 0)
      t.stretch_acc = -t.stretch_inverse * (t.stretch_lin.dot(d) + t.stretch_rot.dot(alpha) + t.stretch_bias);
      d += t.stretch_acc * u;
    }
  }
  tip_delta_ = d;
  // Joint forces from the tip inwards, J_k = J_{k+1} + (the link's inertia force less its loads), for
  // the tensions the next linearization's geometric stiffness reads.
  Eigen::Vector3d joint = load_mass * d + tip_bias;
  tip_tension_ = -joint.dot(blocks.get(&LinkBlock::u, n - 1));
  for (int k = n - 1; k >= first; --k) {
    StiffLinkTerms& t = links_[k];
    if (axial) {  // the far-end point, at joint k + 1's acceleration
      const Eigen::Vector3d far_delta = k + 1 < n ? links_[k + 1].delta_acc : tip_delta_;
      const Eigen::Vector3d u = blocks.get(&LinkBlock::u, k);
      joint += data.deployed.get(&LinkConstants::far_mass, k) * far_delta + (cd * t.far_damping * u.dot(far_delta)) * u +
               t.far_bias;
    }
    joint += t.own_vr * t.angular_acc + t.own_vv * t.delta_acc + t.own_bias;
    t.tension = -joint.dot(blocks.get(&LinkBlock::u, k));
  }
}

}  // namespace cable_dynamics
