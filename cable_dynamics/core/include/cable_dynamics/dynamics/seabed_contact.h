#pragma once
/// \file
/// \brief Contact of the cable and its load with the seabed (docs/MODEL.md section 10): a normal
///        spring-damper per unit length at points along each link, regularized Coulomb friction with
///        separate axial and lateral coefficients, its potential energy and its dissipation.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/dynamics/seabed.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

class ChainModel;
struct ChainData;

/// The contact's constants, derived once from the parameters (ChainModel::seabedContact()).
struct SeabedContactConstants {
  Seabed bed;
  int points = 0;                   ///< contact points per link (midpoint rule)
  double node[16] = {};             ///< their places along a link, as fractions of its length [-]
  double stiffness = 0.0;           ///< k, normal stiffness per unit length [N/m^2]
  /// delta_s = w'_max / k, the heaviest section's resting penetration [m]: the damper ramps in over it,
  /// so that the normal force is continuous when a point touches down.
  double rest_penetration = 1.0;
  double allowed_penetration = 0.0; ///< what a run must stay within (seabed.penetration) [m]
  double friction_axial = 0.0, friction_lateral = 0.0;  ///< Coulomb coefficients [-]
  double friction_velocity = 0.01;  ///< regularization speed [m/s]
  std::vector<double> damping;      ///< (n) c = 2 zeta sqrt(k (m' + m_a')) of each slot's section [N s/m^2]
  // The load, a point (load modes free and anchored; an attached ROV's own contact is its simulator's).
  bool load_contact = false;
  double load_stiffness = 0.0;      ///< 100 W / penetration [N/m]
  double load_damping = 0.0;        ///< 2 zeta sqrt(k (m + m_a)) [N s/m]
  double load_rest = 1.0;           ///< W / k [m]

  bool enabled() const { return bed.enabled(); }
};

/// Builds the constants from the validated parameters and the per-link properties.
SeabedContactConstants makeSeabedContact(const CableParams& params, const LinkProperties& properties);

/// One contact point's force [N] (paper frame) and the power it dissipates [W] (>= 0: the damper and
/// the friction, less nothing the spring stores).
struct PointContact {
  Vec3 force{0.0, 0.0, 0.0};
  double dissipation = 0.0;
  double penetration = 0.0;  ///< [m]
};

/// The contact of a point at p moving at v, standing for `share` metres of cable with axis `axis`
/// (`share` 1 and a zero axis for the load: friction isotropic at the lateral coefficient); stiffness
/// `k` and damping `c` per share, resting penetration `rest`. false (and `out` untouched) when the
/// point is above the bed.
/// Inline: it runs for every contact point of every evaluation.
EIGEN_ALWAYS_INLINE bool pointContact(const SeabedContactConstants& c, double share, double k, double damping, double rest,
                                     const Vec3& p, const Vec3& v, const Vec3& axis, PointContact& out) {
  const SeabedProbe probe = c.bed.probe(p.x, p.y);
  const double delta = Seabed::penetration(probe, p.z);
  if (delta <= 0.0) return false;
  const Vec3 n = probe.into;
  const double rate = dot(v, n);  // penetration rate [m/s]
  // Spring and damper; the damper ramps in over the resting penetration (continuous at touchdown),
  // and the bed only pushes (a point leaving fast feels nothing rather than a pull).
  const double ramp = std::min(1.0, delta / rest);
  const double spring = share * k * delta;
  const double normal = std::max(0.0, spring + share * damping * ramp * rate);  // [N]
  Vec3 force = -normal * n;
  // What the spring does not store is dissipated: (N - k delta share) delta' >= 0 (the damper's
  // c ramp delta'^2 share, or, when the bed lets go, -k delta delta' share with delta' < 0).
  double dissipation = (normal - spring) * rate;
  if (normal > 0.0 && (c.friction_axial > 0.0 || c.friction_lateral > 0.0)) {
    const Vec3 slip = v - rate * n;  // in the bed's tangent plane
    const double speed = std::sqrt(dot(slip, slip));
    // Coulomb above the regularization speed, viscous below it (continuous; zero at rest).
    const double scale = normal / std::max(speed, c.friction_velocity);
    const Vec3 along = axis - dot(axis, n) * n;
    const double along_squared = dot(along, along);
    Vec3 friction;
    if (along_squared > 1e-12) {
      const Vec3 unit = (1.0 / std::sqrt(along_squared)) * along;
      const Vec3 axial = dot(slip, unit) * unit;
      friction = -scale * (c.friction_axial * axial + c.friction_lateral * (slip - axial));
    } else {
      friction = -(scale * c.friction_lateral) * slip;  // the load, or a link standing on end
    }
    force = force + friction;
    dissipation -= dot(friction, slip);
  }
  out.force = force;
  out.dissipation = dissipation;
  out.penetration = delta;
  return true;
}


/// What the outputs show of the contact at one state (paper frame).
struct SeabedReport {
  Eigen::Matrix3Xd link_force;  ///< (3 x n) the seabed's force on each link, normal and friction [N]
  Eigen::VectorXd normal_force; ///< (n) its normal part's magnitude [N]
  Eigen::Vector3d load_force = Eigen::Vector3d::Zero();  ///< on the load [N]
  double grounded_length = 0.0;  ///< cable length in contact [m]
  bool touching = false;         ///< any point of the cable in contact
  /// From the base, where the cable first enters the bed [m]: the signed penetration interpolated
  /// linearly between the contact points on either side of zero.
  double touchdown_arc_length = 0.0;
  Eigen::Vector3d touchdown = Eigen::Vector3d::Zero();  ///< that point, on the link's axis [m]
  double max_penetration = 0.0;  ///< largest, cable and load [m]
  double energy = 0.0;           ///< the springs' potential energy [J]
};

/// Adds the seabed's forces to each link's force and first moment and to the load's external force,
/// and sets data.contact_dissipation [W]; after the rest of the external loads of the same state. O(n);
/// a block of eight links wholly above the shallowest depth costs one comparison.
void addSeabedContact(const ChainModel& model, ChainData& data);

/// The same contact at the kinematics in `data`, for the outputs: forces per link, grounded length,
/// touchdown, penetration, energy (allocates `report` on first use; not the hot path).
void reportSeabedContact(const ChainModel& model, const ChainData& data, SeabedReport& report);

/// The contact springs' potential energy sum 1/2 k delta^2 share at the kinematics in `data` [J].
double seabedContactEnergy(const ChainModel& model, const ChainData& data);

}  // namespace cable_dynamics
