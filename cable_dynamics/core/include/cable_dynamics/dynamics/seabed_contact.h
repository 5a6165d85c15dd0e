#pragma once
/// \file
/// \brief Contact of the cable and its load with the seabed (docs/MODEL.md section 10): a normal
///        spring-damper per unit length at points along each link, Coulomb friction with static friction
///        (an anchor per contact point) and separate axial and lateral coefficients, its potential energy
///        and its dissipation.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/forces/contact.h"
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
  double friction_breakout = 0.0;   ///< the anchors' reach x_b [m]; 0: no static friction
  std::vector<double> damping;      ///< (n) c = 2 zeta sqrt(k (m' + m_a')) of each slot's section [N s/m^2]
  // The load, a point (load modes free and anchored; an attached ROV's own contact is its simulator's).
  bool load_contact = false;
  double load_stiffness = 0.0;      ///< 100 W / penetration [N/m]
  double load_damping = 0.0;        ///< 2 zeta sqrt(k (m + m_a)) [N s/m]
  double load_rest = 1.0;           ///< W / k [m]

  bool enabled() const { return bed.enabled(); }
  /// Static friction: each contact point has an anchor (ChainData::anchors).
  bool anchored() const { return enabled() && friction_breakout > 0.0 && (friction_axial > 0.0 || friction_lateral > 0.0); }
  /// The law of a contact point of slot k standing for `share` metres of it, its spring scaled by
  /// `spring_scale` (the statics' continuation; 1 otherwise).
  ContactLaw linkLaw(int k, double share, double spring_scale = 1.0) const {
    return {share * (spring_scale * stiffness), share * damping[k], rest_penetration, friction_axial, friction_lateral,
            friction_velocity, friction_breakout};
  }
  /// The load's law (a point: isotropic friction).
  ContactLaw loadLaw(double spring_scale = 1.0) const {
    return {spring_scale * load_stiffness, load_damping, load_rest, friction_axial, friction_lateral, friction_velocity,
            friction_breakout};
  }
};

/// Builds the constants from the validated parameters and the per-link properties.
SeabedContactConstants makeSeabedContact(const CableParams& params, const LinkProperties& properties);

/// Where the point p of a link with axis `axis` (zero for the load) is against the bed: false above it.
/// Geometry only; the law is dynamics/forces/contact.h.
EIGEN_ALWAYS_INLINE bool contactPlace(const Seabed& bed, const Vec3& p, const Vec3& axis, ContactPlace& place) {
  const SeabedProbe probe = bed.probe(p.x, p.y);
  place.delta = Seabed::penetration(probe, p.z);
  if (place.delta <= 0.0) return false;
  place.normal = probe.into;
  place.has_along = alongTheBed(axis, place.normal, place.along);
  return true;
}

/// Places the friction's anchors (ChainData::anchors; nothing without static friction) at the kinematics in
/// `data`. `slide` false: every anchor at its point (no friction force from an offset: a new state, the
/// statics' equilibrium). `slide` true, after each accepted step: an anchor beyond its reach x_b from its point
/// (along the bed) slides to x_b behind it, the Coulomb law's slip; a point off the bed takes its anchor
/// with it; and the winch's link, whose points move along the cable as its length changes, keeps its
/// anchors on its points (regularized friction only), as do the `winch_links` first deployed links in all
/// (2 after the winch added or removed a link: the link it split or merged too). O(n).
void placeContactAnchors(const ChainModel& model, ChainData& data, bool slide, int winch_links = 1);

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
  /// Static friction: the grounded cable whose anchors hold it (offset below x_b and no faster than the
  /// regularization speed) [m]; 0 without static friction.
  double stuck_length = 0.0;
};

/// Adds the seabed's forces to each link's force and first moment and to the load's external force,
/// and sets data.contact_dissipation [W]; after the rest of the external loads of the same state. O(n);
/// a block of eight links wholly above the shallowest depth costs one comparison.
void addSeabedContact(const ChainModel& model, ChainData& data);

/// The velocity change at which an implicit step's stage takes the contact's dampers and friction: its
/// W-method solves the stage with the forces at v + dv (the linearized damping times the stage's own
/// velocity change), not at the stage's v. Per link, the base end's dv [m/s] and the angular velocity's
/// dw [rad/s] (3 x n each, columns by link); the load's dv [m/s].
struct ContactVelocityShift {
  const Eigen::Matrix3Xd* base = nullptr;
  const Eigen::Matrix3Xd* omega = nullptr;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
};

/// The seabed's dissipated power [W] at the kinematics in `data` with every contact point moving at its
/// velocity plus `shift` (the positions and the anchors as they are), nothing added to any force. The
/// implicit step books its stages' losses with it: the dissipation at the stage's start velocity
/// over-counts a stiff contact damper that stops a point within the step (a chain landing in air at
/// 10 ms, h c / m about 5: 7 times the kinetic energy it took; docs/MODEL.md section 6). O(n), no
/// allocation.
double seabedContactDissipation(const ChainModel& model, const ChainData& data, const ContactVelocityShift& shift);

/// The same contact at the kinematics in `data`, for the outputs: forces per link, grounded length,
/// touchdown, penetration, energy (allocates `report` on first use; not the hot path).
void reportSeabedContact(const ChainModel& model, const ChainData& data, SeabedReport& report);

/// The contact springs' potential energy sum 1/2 k delta^2 share at the kinematics in `data` [J].
double seabedContactEnergy(const ChainModel& model, const ChainData& data);

}  // namespace cable_dynamics
