#include "static_equations.h"

#include <algorithm>
#include <cmath>

#include "cable_dynamics/dynamics/forces/contact.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/fold_stop.h"
#include "cable_dynamics/dynamics/forces/joint_springs.h"
#include "cable_dynamics/dynamics/forces/point_drag.h"
#include "cable_dynamics/dynamics/forces/tip_clamp.h"

namespace cable_dynamics {
namespace statics {

StaticEquations::StaticEquations(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                                 const StaticProblem& problem)
    : model_(model),
      deployed_(deployed),
      current_(current),
      problem_(problem),
      first_(problem.first_link),
      m_(model.links() - problem.first_link),
      length_(m_),
      weight_(m_),
      weight_moment_(m_),
      bend_stiffness_(m_),
      fold_diameter_(m_) {
  const LinkProperties& p = deployed.properties();
  const bool bending = model.stiffnessModel() == StiffnessModel::kBending;
  for (int i = 0; i < m_; ++i) {
    const int k = first_ + i;
    // With axial elasticity the lever to the far end is l + s; the link's own mass stays on its l.
    length_(i) = deployed.get(&LinkConstants::length, k) + (problem.stretch.size() > k ? problem.stretch(k) : 0.0);
    // The attachments' included, and the far-end point's beyond the stretch (axial elasticity), l + s out.
    const double far_weight = deployed.get(&LinkConstants::far_weight, k);
    weight_(i) = deployed.get(&LinkConstants::weight, k) + far_weight;
    weight_moment_(i) = deployed.get(&LinkConstants::weight_moment, k) + length_(i) * far_weight;
    // A winch pays out from the drum: the first deployed link leaves the base's clamp, with the spring of
    // the joint it has in the model.
    bend_stiffness_(i) = bending ? p.stiffness_elevation(k) : 0.0;
    fold_diameter_(i) = 2.0 * std::max(p.radius(k), k > first_ ? p.radius(k - 1) : 0.0);
  }
  fold_tension_ = bending ? model.foldStopTension() : 0.0;
  has_bend_ = (bend_stiffness_.array() > 0.0).any();
  in_water_ = model.fluidDensity() > 0.0;
  // An exact anchor's statics hold the tip with a spring whose target solveStatics shifts until the tip
  // sits on the anchor; otherwise the coupling spring.
  coupling_stiffness_ = !problem.tip_coupled          ? 0.0
                        : model.holdStiffness() > 0.0 ? staticHoldStiffness(model)
                                                      : model.load().coupling().stiffnessJacobian();
  clamp_axis_ = problem.clamp_moves ? problem.clamp_axis : p.clamp_axis;
  tip_clamp_stiffness_ = problem.tip_coupled ? p.tip_clamp_stiffness : 0.0;
  tip_clamp_axis_ = problem.tip_clamp_moves ? problem.tip_clamp_axis : p.tip_clamp_axis;
  has_bend_ = has_bend_ || tip_clamp_stiffness_ > 0.0;
}

void StaticEquations::linkLoads(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p, Eigen::Vector3d& force,
                                Eigen::Vector3d& moment) const {
  const int k = first_ + i;
  const double l = length_(i);
  force = Eigen::Vector3d(0.0, 0.0, weight_(i));
  moment = Eigen::Vector3d(0.0, 0.0, weight_moment_(i));
  addSeabedContact(i, u, p, force, moment);
  if (!in_water_) return;
  // The same quadrature as the dynamics, at zero velocity: the relative velocity is the current alone.
  Eigen::Vector3d drag_force, drag_moment;
  model_.drag().pointwise(current_, l, deployed_.dragCoefficients(k), p, Eigen::Vector3d::Zero(), u, Eigen::Vector3d::Zero(),
                          drag_force, drag_moment);
  force += drag_force;
  moment += drag_moment;
  // The far half's skin friction on the far-end point, at l + s along u (axial elasticity).
  const double far = farDrag(i, u, p);
  force += far * u;
  moment += (l * far) * u;
  // The attachments' drag in the current at their points (external_loads.cpp at zero velocity).
  for (int a = model_.attachmentBegin(k); a < model_.attachmentBegin(k + 1); ++a) {
    const LinkAttachment& point = model_.attachments()[a];
    if (point.drag_area <= 0.0) continue;
    const Eigen::Vector3d at = p + point.offset * u;
    const Eigen::Vector3d drag = pointDragAtRest(model_.fluidDensity(), point.drag_area, current_.at(at.z()));
    force += drag;
    moment += point.offset * drag;
  }
}

double StaticEquations::farDrag(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p) const {
  const int k = first_ + i;
  const double coefficient = deployed_.get(&LinkConstants::far_tangential, k);
  if (!in_water_ || coefficient == 0.0) return 0.0;
  const double along = u.dot(current_.at(p.z() + length_(i) * u.z()));  // the flow past the point at rest
  // On the far half of the stretched length, as linkLoads puts the body's drag on l + s.
  return coefficient * (length_(i) / deployed_.get(&LinkConstants::length, k)) * std::abs(along) * along;
}

void StaticEquations::addSeabedContact(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p, Eigen::Vector3d& force,
                                       Eigen::Vector3d& moment) const {
  const SeabedContactConstants& c = model_.seabedContact();
  if (!c.enabled() || contact_scale_ == 0.0) return;
  // The contact points of seabed_contact.cpp at rest: the springs alone (the dampers and the
  // friction act on velocities; a friction that holds a cable at rest is not a static unknown here).
  const int k = first_ + i;
  const double l = length_(i);
  const ContactLaw law = c.linkLaw(k, l / c.points, contact_scale_);
  for (int j = 0; j < c.points; ++j) {
    const double s = c.node[j] * l;
    ContactPlace place;
    if (contactPlace(c.bed, toVec3(p + s * u), toVec3(u), place)) {
      const Eigen::Vector3d f = contactForceAtRest(law, place);
      force += f;
      moment += s * f;
    }
  }
}

bool StaticEquations::touchesSeabed(const StaticState& s) const {
  const SeabedContactConstants& c = model_.seabedContact();
  if (!c.enabled()) return false;
  for (int i = 0; i < m_; ++i) {
    for (int j = 0; j < c.points; ++j) {
      const Eigen::Vector3d p = s.base.col(i) + (c.node[j] * length_(i)) * s.axis.col(i);
      if (Seabed::penetration(c.bed.probe(p.x(), p.y()), p.z()) > 0.0) return true;
    }
  }
  const Eigen::Vector3d t = tip(s);
  return c.load_contact && Seabed::penetration(c.bed.probe(t.x(), t.y()), t.z()) > 0.0;
}

Eigen::Vector3d StaticEquations::loadForceFree(const Eigen::Vector3d& tip) const {
  const LoadConstants& load = model_.load();
  Eigen::Vector3d f(0.0, 0.0, load.weight);
  const SeabedContactConstants& c = model_.seabedContact();
  ContactPlace place;
  if (c.load_contact && contact_scale_ > 0.0 && contactPlace(c.bed, toVec3(tip), {0.0, 0.0, 0.0}, place)) {
    f += contactForceAtRest(c.loadLaw(contact_scale_), place);
  }
  if (in_water_ && load.drag_area > 0.0) f += pointDragAtRest(model_.fluidDensity(), load.drag_area, current_.at(tip.z()));
  const RovBodyConstants& body = model_.body();
  if (body.active) {
    // An ROV body held level at rest (its attitude settles in the dynamics): its submerged weight, and its
    // translational damping in the current, -D(nu_r) nu_r with nu_r = -R^T v_c (R: level, paper from body).
    f.z() += body.weight - body.buoyancy;
    const Eigen::Matrix3d level = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
    const Eigen::Vector3d flow = level.transpose() * current_.at(tip.z());
    const Eigen::Array3d d = body.linear_damping.head<3>().array() + body.quadratic_damping.head<3>().array() * flow.array().abs();
    f += level * (d * flow.array()).matrix();
  }
  return f;
}

Eigen::Vector3d StaticEquations::couplingForce(const Eigen::Vector3d& tip) const {
  if (!problem_.tip_coupled) return Eigen::Vector3d::Zero();
  return LoadCoupling{coupling_stiffness_, 0.0}.atRest(tip, problem_.target_position);
}

Eigen::Vector3d StaticEquations::outboardForce(const StaticState& s, int i) const {
  if (i + 1 < m_) return s.force.col(i + 1);
  const Eigen::Vector3d t = tip(s);
  return -(loadForceFree(t) + couplingForce(t));  // the load in equilibrium: J_n + F_load = 0
}

Eigen::Vector3d StaticEquations::bendTorque(int i, const Eigen::Vector3d& prev, const Eigen::Vector3d& axis) const {
  const double k = stiffness_scale_ * bend_stiffness_(i);
  Eigen::Vector3d torque = k == 0.0 ? Eigen::Vector3d::Zero() : bendSpringTorque(k, prev, axis);  // as joint_torques.cpp's
  // A joint folded onto its neighbour: the fold stop (forces/fold_stop.h), a contact, not ramped with the
  // springs. Between two links only (i > 0), as in the dynamics.
  if (i > 0 && prev.dot(axis) < 0.0) {
    const Eigen::Vector3d cross = prev.cross(axis);
    const double sine = cross.norm(), bend = std::atan2(sine, prev.dot(axis));
    torque += FoldStop::between(length_(i - 1), length_(i), fold_diameter_(i), fold_tension_).torque(bend, sine, cross);
  }
  return torque;
}

void StaticEquations::residual(const StaticState& s, int i, LinkResidual& r) const {
  const Eigen::Vector3d u = s.axis.col(i), p = s.base.col(i);
  Eigen::Vector3d f, n;
  linkLoads(i, u, p, f, n);
  const Eigen::Vector3d next = outboardForce(s, i);
  r.force = s.force.col(i) - next + f;
  // Joint i (from link i-1 or the clamp) and joint i+1 (to link i+1); the twists are zero, so only the
  // bend springs remain, and both torques are normal to u_i.
  Eigen::Vector3d torque = bendTorque(i, i > 0 ? Eigen::Vector3d(s.axis.col(i - 1)) : clamp_axis_, u);
  if (i + 1 < m_) torque -= bendTorque(i + 1, u, s.axis.col(i + 1));
  if (i + 1 == m_ && tip_clamp_stiffness_ > 0.0) {
    // The tip's clamp at rest (forces/tip_clamp.h): its spring's torque on the last link.
    torque -= TipClamp{stiffness_scale_ * tip_clamp_stiffness_, 0.0}.springOnClamp(u, tip_clamp_axis_);
  }
  r.moment = u.cross(n - length_(i) * next) + torque;
  r.closure = i > 0 ? Eigen::Vector3d(p - s.base.col(i - 1) - length_(i - 1) * s.axis.col(i - 1))
                    : Eigen::Vector3d(p - problem_.base_position);
}

double StaticEquations::forceScale(const StaticState& s) const {
  double scale = 0.0;
  for (int i = 0; i < m_; ++i) {
    Eigen::Vector3d f, n;
    linkLoads(i, s.axis.col(i), s.base.col(i), f, n);
    scale += f.norm();
  }
  const Eigen::Vector3d t = tip(s);
  scale += loadForceFree(t).norm() + couplingForce(t).norm();
  return std::max(scale, 1e-9);
}

}  // namespace statics
}  // namespace cable_dynamics
