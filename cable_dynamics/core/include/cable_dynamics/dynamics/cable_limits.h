#pragma once
/// \file
/// \brief The engineering limits at one evaluated state (docs/MODEL.md section 13): the bend radius at
///        each joint, each link's utilisation against the safe working load and its section's minimum
///        bend radius, and the seabed clearance. Computed once, in ChainDynamics::evaluate (the snapshot's
///        path); every output (cable_sim's CSV, Python, the node) reads it from there.

#include <limits>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/seabed_contact.h"

namespace cable_dynamics {

/// What the limits say about one state. Slots on a winch's drum: radius +inf, utilisation 0.
struct LimitReport {
  static constexpr double kStraight = std::numeric_limits<double>::infinity();
  /// (n) joint k's bend radius [m]: joint k joins link k-1 and link k; joint 0 bends link 0 against the
  /// base's clamp (+inf at a pinned base or with the paper model). +inf where the joint is straight.
  Eigen::VectorXd bend_radius;
  /// (n) each link's utilisation [-]: the larger of its largest tension / cable.limits.max_tension and its
  /// section's minimum bend radius / its own bend radius (the smaller of its two end joints', the tip's
  /// clamp counting as the last link's far joint); an absent limit contributes 0. 1 = at a limit.
  Eigen::VectorXd utilisation;
  double min_bend_radius = kStraight;  ///< the smallest link bend radius [m]
  int min_bend_radius_link = 0;        ///< its link (0-based; the first deployed link when all are straight)
  double max_utilisation = 0.0;        ///< [-]
  int max_utilisation_link = 0;        ///< its link (0-based; the first deployed link when all are 0)
  /// The two limits apart (for the diagnostics: which limit, on which link).
  double max_tension_utilisation = 0.0, max_bend_utilisation = 0.0;  ///< [-]
  int max_tension_utilisation_link = 0, max_bend_utilisation_link = 0;
  /// With a seabed: the smallest height above the bottom of a link end that no grounded link touches [m]
  /// (+inf without a seabed, or with every link grounded), and the link it belongs to.
  double seabed_clearance = kStraight;
  int seabed_clearance_link = 0;
  bool tension_exceeded = false;    ///< some link's tension above cable.limits.max_tension
  bool bend_exceeded = false;       ///< some link bent tighter than its minimum bend radius
  bool clearance_exceeded = false;  ///< seabed_clearance below cable.limits.min_seabed_clearance
  bool exceeded() const { return tension_exceeded || bend_exceeded || clearance_exceeded; }
};

/// The bend radius of a joint between links of (stretched) lengths a and b [m] whose unit axes differ by
/// the chord |u_a - u_b| = 2 sin(beta / 2), beta the bend angle: R = (a + b) / (4 sin(beta / 2)). Exact for
/// a regular polygon inscribed in a circle (R = l / (2 sin(beta / 2)) when a = b = l); +inf when straight.
inline double jointBendRadius(double a, double b, double chord) {
  return chord > 0.0 ? (a + b) / (2.0 * chord) : LimitReport::kStraight;
}

/// The bend radius at a clamp of a link of (stretched) length l [m] at the angle theta from the clamp's
/// axis (sine = sin theta, cosine = cos theta): the circle tangent to the clamp's axis through the link's
/// far end, R = l / (2 sin theta), the joint formula with the link mirrored about the clamp (the clamp's
/// spring acts over half a link, so a uniform moment bends it half as much as an inner joint). Beyond
/// theta = 90 degrees, l / 2 (the radius only falls as the bend grows).
inline double clampBendRadius(double l, double sine, double cosine) {
  if (cosine < 0.0) return 0.5 * l;
  return sine > 0.0 ? l / (2.0 * sine) : LimitReport::kStraight;
}

/// Fills `report` at the state `data` holds after a solve (kinematics, joint forces): `tension` (n) is
/// each link's tension at its base end [N] (ChainOutputs::tension), `load_force` the force on the load at
/// the last link's far end [N], `seabed` the contact report (nullptr without a seabed). Sizes the vectors
/// to n on first use; no allocation after (test_no_allocation).
void reportLimits(const ChainModel& model, const ChainData& data, const Eigen::VectorXd& tension,
                  const Eigen::Vector3d& load_force, const SeabedReport* seabed, LimitReport& report);

}  // namespace cable_dynamics
