#include "static_equations.h"

#include <cmath>

#include "cable_dynamics/dynamics/joint_geometry.h"

namespace cable_dynamics {
namespace statics {

StaticEquations::StaticEquations(const ChainModel& model, const CurrentField& current, const StaticProblem& problem)
    : model_(model),
      current_(current),
      problem_(problem),
      first_(problem.first_link),
      m_(model.links() - problem.first_link),
      length_(m_),
      weight_(m_),
      weight_moment_(m_),
      bend_stiffness_(m_) {
  const LinkProperties& p = model.properties();
  const bool bending = model.stiffnessModel() == StiffnessModel::kBending;
  for (int i = 0; i < m_; ++i) {
    const int k = first_ + i;
    length_(i) = model.get(&LinkConstants::length, k);
    weight_(i) = model.get(&LinkConstants::weight, k);  // the attachments' included
    weight_moment_(i) = model.get(&LinkConstants::weight_moment, k);
    // A winch pays out from the drum: the first deployed link leaves the base's clamp, with the spring of
    // the joint it has in the model.
    bend_stiffness_(i) = bending ? p.stiffness_elevation(k) : 0.0;
  }
  has_bend_ = (bend_stiffness_.array() > 0.0).any();
  in_water_ = model.fluidDensity() > 0.0;
  coupling_stiffness_ = problem.tip_coupled ? model.load().coupling_stiffness : 0.0;
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
  model_.drag().pointwise(current_, l, model_.dragCoefficients(k), p, Eigen::Vector3d::Zero(), u, Eigen::Vector3d::Zero(),
                          drag_force, drag_moment);
  force += drag_force;
  moment += drag_moment;
  // The attachments' drag in the current at their points (external_loads.cpp at zero velocity).
  for (int a = model_.attachmentBegin(k); a < model_.attachmentBegin(k + 1); ++a) {
    const LinkAttachment& point = model_.attachments()[a];
    if (point.drag_area <= 0.0) continue;
    const Eigen::Vector3d at = p + point.offset * u;
    const Eigen::Vector3d drag = pointDrag(model_.fluidDensity(), point.drag_area, Eigen::Vector3d::Zero(), current_.at(at.z()));
    force += drag;
    moment += point.offset * drag;
  }
}

void StaticEquations::addSeabedContact(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p, Eigen::Vector3d& force,
                                       Eigen::Vector3d& moment) const {
  const SeabedContactConstants& c = model_.seabedContact();
  if (!c.enabled() || contact_scale_ == 0.0) return;
  // The contact points of seabed_contact.cpp at rest: the springs alone (the dampers and the
  // friction act on velocities; a friction that holds a cable at rest is not a static unknown here).
  const int k = first_ + i;
  const double l = length_(i), share = l / c.points;
  for (int j = 0; j < c.points; ++j) {
    const double s = c.node[j] * l;
    PointContact contact;
    if (pointContact(c, share, contact_scale_ * c.stiffness, c.damping[k], c.rest_penetration, toVec3(p + s * u),
                     {0.0, 0.0, 0.0}, toVec3(u), contact)) {
      force += toEigen(contact.force);
      moment += s * toEigen(contact.force);
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
  PointContact contact;
  if (c.load_contact && contact_scale_ > 0.0 &&
      pointContact(c, 1.0, contact_scale_ * c.load_stiffness, c.load_damping, c.load_rest, toVec3(tip), {0.0, 0.0, 0.0},
                   {0.0, 0.0, 0.0}, contact)) {
    f += toEigen(contact.force);
  }
  if (in_water_ && load.drag_area > 0.0) {
    const Eigen::Vector3d c = current_.at(tip.z());  // [m/s]
    f += 0.5 * model_.fluidDensity() * load.drag_area * c.norm() * c;
  }
  return f;
}

Eigen::Vector3d StaticEquations::couplingForce(const Eigen::Vector3d& tip) const {
  if (!problem_.tip_coupled) return Eigen::Vector3d::Zero();
  return -coupling_stiffness_ * (tip - problem_.target_position);  // the damper is zero at rest
}

Eigen::Vector3d StaticEquations::outboardForce(const StaticState& s, int i) const {
  if (i + 1 < m_) return s.force.col(i + 1);
  const Eigen::Vector3d t = tip(s);
  return -(loadForceFree(t) + couplingForce(t));  // the load in equilibrium: J_n + F_load = 0
}

Eigen::Vector3d StaticEquations::bendTorque(int i, const Eigen::Vector3d& prev, const Eigen::Vector3d& axis) const {
  const double k = stiffness_scale_ * bend_stiffness_(i);
  if (k == 0.0) return Eigen::Vector3d::Zero();
  // As joint_torques.cpp: V = 1/2 k beta^2 gives -k beta/sin(beta) (prev x u) on link i.
  const Eigen::Vector3d cross = prev.cross(axis);
  const double sine = cross.norm(), bend = std::atan2(sine, prev.dot(axis));
  return -k * bendOverSine(bend, sine) * cross;
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
    // The tip's clamp, as joint_torques.cpp: a bend spring from the last link to the clamp's axis.
    const Eigen::Vector3d cross = u.cross(tip_clamp_axis_);
    const double sine = cross.norm(), bend = std::atan2(sine, u.dot(tip_clamp_axis_));
    torque += stiffness_scale_ * tip_clamp_stiffness_ * bendOverSine(bend, sine) * cross;
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
