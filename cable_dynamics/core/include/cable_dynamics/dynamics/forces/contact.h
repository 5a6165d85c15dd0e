#pragma once
/// \file
/// \brief The seabed's contact law at one point (docs/MODEL.md section 10): its value (force and the power
///        it dissipates), its potential energy, its Jacobian (for the implicit step) and its form at rest
///        (for the statics), side by side. The bed's geometry (where a point is, how deep, the normal)
///        is Seabed's; the passes over the links and the load are seabed_contact.cpp (explicit),
///        stiff_articulated_body.cpp (the linearization) and static_equations.cpp (the statics), and
///        all of them read the law from here.
///
/// The law, for a point standing for `share` metres of cable (1 for the load) at penetration delta > 0
/// with the bed's inward normal n, moving at v: a normal spring-damper
///   N = max(0, share k delta + share c ramp delta'),  ramp = min(1, delta / rest),  delta' = v . n,
/// (the damper ramps in over the resting penetration, so that the force is continuous at touchdown, and
/// the bed only pushes), and regularized Coulomb friction on the slip s = v - delta' n,
///   f = -N / max(|s|, v_r) (mu_a (s.a) a + mu_l (s - (s.a) a)),
/// with a the unit direction of the link's axis along the bed (isotropic at mu_l where there is none: the
/// load, a link standing on end). The force on the point is -N n + f.

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/link_block.h"

namespace cable_dynamics {

/// The law's coefficients for one point: its share of the spring k and damper c (per share), the resting
/// penetration over which the damper ramps in, and the friction's (from SeabedContactConstants).
struct ContactLaw {
  double stiffness = 0.0;  ///< share k [N/m]
  double damping = 0.0;    ///< share c [N s/m]
  double rest = 1.0;       ///< the damper's ramp length [m]
  double friction_axial = 0.0, friction_lateral = 0.0;  ///< Coulomb coefficients [-]
  double friction_velocity = 0.01;  ///< regularization speed v_r [m/s]

  bool hasFriction() const { return friction_axial > 0.0 || friction_lateral > 0.0; }
};

/// Where a point is against the bed: its penetration (> 0 in contact) [m], the bed's unit inward normal,
/// the unit direction of the link's axis along the bed (`has_along` false: none, isotropic friction).
struct ContactPlace {
  double delta = 0.0;
  Vec3 normal{0.0, 0.0, 1.0};
  Vec3 along{0.0, 0.0, 0.0};
  bool has_along = false;
};

/// The unit direction along the bed (normal n) of an axis [-]; false when the axis is (nearly) normal to it.
EIGEN_ALWAYS_INLINE bool alongTheBed(const Vec3& axis, const Vec3& n, Vec3& along) {
  const Vec3 projected = axis - dot(axis, n) * n;
  const double squared = dot(projected, projected);
  if (squared <= 1e-12) return false;
  along = (1.0 / std::sqrt(squared)) * projected;
  return true;
}

/// One contact point's force [N] (paper frame) and the power it dissipates [W] (>= 0: the damper and
/// the friction; what the spring does not store).
struct PointContact {
  Vec3 force{0.0, 0.0, 0.0};
  double dissipation = 0.0;
  double penetration = 0.0;  ///< [m]
};

/// The normal force N [N] at penetration delta [m] and penetration rate [m/s] (>= 0: the bed only pushes).
EIGEN_ALWAYS_INLINE double contactNormalForce(const ContactLaw& law, double delta, double rate) {
  const double ramp = std::min(1.0, delta / law.rest);
  return std::max(0.0, law.stiffness * delta + law.damping * ramp * rate);
}

/// The law's value at a point in contact (place.delta > 0) moving at v [m/s]. Inline: it runs for every
/// contact point of every evaluation.
EIGEN_ALWAYS_INLINE void contactForce(const ContactLaw& law, const ContactPlace& place, const Vec3& v, PointContact& out) {
  const Vec3 n = place.normal;
  const double rate = dot(v, n);  // penetration rate [m/s]
  const double spring = law.stiffness * place.delta;
  const double normal = contactNormalForce(law, place.delta, rate);
  Vec3 force = -normal * n;
  // What the spring does not store is dissipated: (N - k delta share) delta' >= 0 (the damper's
  // c ramp delta'^2 share, or, when the bed lets go, -k delta delta' share with delta' < 0).
  double dissipation = (normal - spring) * rate;
  if (normal > 0.0 && law.hasFriction()) {
    const Vec3 slip = v - rate * n;  // in the bed's tangent plane
    // Coulomb above the regularization speed, viscous below it (continuous; zero at rest).
    const double scale = normal / std::max(std::sqrt(dot(slip, slip)), law.friction_velocity);
    Vec3 friction;
    if (place.has_along) {
      const Vec3 axial = dot(slip, place.along) * place.along;
      friction = -scale * (law.friction_axial * axial + law.friction_lateral * (slip - axial));
    } else {
      friction = -(scale * law.friction_lateral) * slip;
    }
    force = force + friction;
    dissipation -= dot(friction, slip);
  }
  out.force = force;
  out.dissipation = dissipation;
  out.penetration = place.delta;
}

/// The contact spring's potential energy at penetration delta > 0 [J]: 1/2 share k delta^2.
inline double contactEnergy(const ContactLaw& law, double delta) { return 0.5 * law.stiffness * delta * delta; }

/// The law's Jacobian at a point in contact moving at v: the stiffness -dF/dx ~ share k n n^T (the bed's
/// curvature and the damper's ramp left out) and the damping -dF/dv ~ share c ramp n n^T plus the
/// friction's secant N / max(|s|, v_r) times its coefficients over the tangent plane (the regularized
/// viscous band, the stiff part, exactly; above it the secant, not the tangent). Both are exact where the
/// point does not slip, the ramp is full (delta >= rest) and the bed is flat (test_force_modules).
/// An approximation elsewhere is what the implicit step's W-method allows: it costs no order.
inline void contactJacobian(const ContactLaw& law, const ContactPlace& place, const Eigen::Vector3d& v,
                            Eigen::Matrix3d& stiffness, Eigen::Matrix3d& damping) {
  const Eigen::Vector3d n = toEigen(place.normal);
  const double rate = v.dot(n), ramp = std::min(1.0, place.delta / law.rest);
  const double normal = contactNormalForce(law, place.delta, rate);
  const Eigen::Matrix3d nn = n * n.transpose();
  stiffness = law.stiffness * nn;
  damping = (law.damping * ramp) * nn;
  if (normal > 0.0 && law.hasFriction()) {
    const Eigen::Vector3d slip = v - rate * n;
    const double scale = normal / std::max(slip.norm(), law.friction_velocity);
    const Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity() - nn;
    if (place.has_along) {
      const Eigen::Vector3d a = toEigen(place.along);
      const Eigen::Matrix3d aa = a * a.transpose();
      damping += scale * (law.friction_axial * aa + law.friction_lateral * (tangent - aa));
    } else {
      damping += (scale * law.friction_lateral) * tangent;
    }
  }
}

/// The law at rest (v = 0: no damper, no friction), for the statics: the spring's force -share k delta n [N].
inline Eigen::Vector3d contactForceAtRest(const ContactLaw& law, const ContactPlace& place) {
  return -(law.stiffness * place.delta) * toEigen(place.normal);
}

}  // namespace cable_dynamics
