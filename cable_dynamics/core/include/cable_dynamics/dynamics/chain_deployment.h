#pragma once
/// \file
/// \brief The cable as the winch has deployed it now: the per-link constants every pass reads (the drum's
///        slots empty, the winch's link at its present length) and the moments of the joints the winch has
///        just made. Part of the data (ChainData::deployed), because a step changes it; the constant
///        ChainModel writes it (ChainModel::deploy, setWinchLinkLength), and only the model can.
///
/// Without a winch it is set once, at construction, to the configured cable: firstLink() is 0 and every
/// slot keeps its configured constants.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// A joint the winch has just made (docs/MODEL.md section 8, "A link added"): when the winch's link
/// splits, the new joint between its two parts starts with the moment the rigid link held there
/// (`initial`, a torque on link `joint` from link `joint - 1`, world axes [N m]; it acts across the
/// two links' mean axis, its part along it dropped as they turn) and lets it go as the
/// winch pays out the next kJointHoldLinks links: after a paid-out length d = s `span` (`span` the length
/// of the link split off, the distance to the next split) it holds jointHoldLeft(s) of it. Or in
/// kJointHoldLongest seconds from `start` [s], whichever is sooner. An internal pair of torques (the
/// momentum does not change); its power is booked with the losses.
struct JointHold {
  int joint = -1;
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();
  double start = 0.0, deployed = 0.0, span = 1.0;  ///< [s], the deployed length at the split [m], [m]
  /// A damper on the joint's relative turning rate (the links' u x u'), across the two links' mean axis,
  /// let go with the moment [N m s]: a damping rate times the joint's relative inertia across the axis
  /// (the smaller of its two values).
  double damping = 0.0;
  double fraction = 1.0;                           ///< held now (at the last ChainDeployment::setHoldState)
  Eigen::Vector3d now = Eigen::Vector3d::Zero();   ///< fraction * initial
};

/// The held joint's damper over its relative inertia [1/s]. The moment the rigid link held changes as
/// the joint moves out from the winch (near a clamp, quickly), and a fixed held moment misses that
/// change: the damper keeps what it misses from swinging the joint, and lets go with the held moment.
/// rov_dive.yaml's line pull about its 2 s mean: 0.56 % rms (1.40 % peak) without it, 0.44 % (0.80 %)
/// at 60/s, 0.32 % (0.58 %) at 200/s; a stiff tether's 0.04 % either way. No integrator's linearization
/// holds it: at most kJointHoldDampingStep / dt (the implicit integrator at 10 ms: 50/s).
constexpr double kJointHoldDampingRate = 200.0;
constexpr double kJointHoldDampingStep = 0.5;

/// The links paid out while a new joint lets its moment go; each of the joints then lets go at the rate
/// of a hat of width kJointHoldLinks links, and the hats of successive joints sum to one: at a steady
/// pay-out the moment let go per metre does not jump where a link is added.
constexpr int kJointHoldLinks = 2;
/// The fraction held after s links paid out: 1 - the integral of the hat, 1 - s^2/2 on [0, 1],
/// (2 - s)^2/2 on [1, 2], 0 after (its rate is continuous: a smooth start and end).
inline double jointHoldLeft(double s) {
  if (s <= 0.0) return 1.0;
  if (s >= 2.0) return 0.0;
  return s < 1.0 ? 1.0 - 0.5 * s * s : 0.5 * (2.0 - s) * (2.0 - s);
}
/// The longest a new joint's hold lasts [s]: a winch that stops or pays out slowly lets it go in this time.
constexpr double kJointHoldLongest = 10.0;

/// The deployed cable: slots [0, firstLink()) are on the drum, massless and of zero length; slot
/// firstLink() is the winch's link, whose length follows the deployed length. Sized once (no allocation
/// when the winch adds or removes a link, or between evaluations).
class ChainDeployment {
 public:
  /// The first deployed slot, the link at the base (0 without a winch).
  int firstLink() const { return first_; }
  /// The block that holds it: the loops over blocks start there (the drum's blocks before it are idle).
  int firstBlock() const { return first_ / kBlockLanes; }
  /// Per-link description of the cable as now deployed (the drum's slots: zero length and mass; the
  /// winch's link: its present length; the base's joint springs at slot firstLink()).
  const LinkProperties& properties() const { return properties_; }

  /// Per-link constants, eight links a block; lanes past the last link hold a massless link of zero length.
  int blocks() const { return static_cast<int>(lanes_.size()); }
  const LinkConstants& block(int b) const { return lanes_[b]; }
  const LinkConstants& of(int k) const { return lanes_[k / kBlockLanes]; }
  /// Scalar constant `field` of link k, e.g. get(&LinkConstants::length, k).
  double get(double (LinkConstants::*field)[kBlockLanes], int k) const { return (of(k).*field)[k % kBlockLanes]; }
  /// Link k's Morison coefficients 1/2 rho C_n d and 1/2 rho C_t pi d (its section's; 0 on the drum) [kg/m^2].
  DragCoefficients dragCoefficients(int k) const {
    return {get(&LinkConstants::drag_normal, k), get(&LinkConstants::drag_tangential, k)};
  }

  // The joints the winch has just made and the moments they hold (JointHold); at most kMaxJointHolds,
  // the oldest dropped first.
  static constexpr int kMaxJointHolds = kJointHoldLinks + 1;
  /// Holds `joint` with `torque` [N m] and a damper `damping` [N m s] from time `start` [s] and the
  /// deployed length `deployed` [m], let go over kJointHoldLinks times `span` [m] of pay-out; replaces a
  /// hold of the same joint.
  void holdJoint(int joint, const Eigen::Vector3d& torque, double damping, double start, double deployed,
                 double span);
  /// Each hold's fraction and moment at time t [s] and deployed length `deployed` [m]
  /// (JointHold::fraction, now). O(holds); every evaluation calls it.
  void setHoldState(double t, double deployed);
  /// Drops the holds let go entirely (fraction 0 at the last setHoldState).
  void dropReleasedHolds();
  void releaseJoints() { hold_count_ = 0; }
  int jointHolds() const { return hold_count_; }
  const JointHold& jointHold(int i) const { return holds_[i]; }

 private:
  friend class ChainModel;  // the only writer of the deployed constants
  void dropHold(int i);     ///< keeps the others in order

  int first_ = 0;
  LinkProperties properties_;
  std::vector<LinkConstants> lanes_;  // C++17's allocator honours the 64-byte alignment
  std::array<JointHold, kMaxJointHolds> holds_{};  ///< the winch's joints made last, while held
  int hold_count_ = 0;
};

}  // namespace cable_dynamics
