#pragma once
/// \file
/// \brief The chain's constants, built once per cable from its parameters and never changed by a step:
///        the "model" half of the model/data split (ChainData holds everything that changes). Live
///        tuning replaces the whole model between steps (CableSimulator::retune).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/tip_clamp.h"
#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/dynamics/rov_body.h"
#include "cable_dynamics/dynamics/seabed_contact.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The terminal load's constants.
struct LoadConstants {
  double mass = 0.0;                ///< in air [kg] (kinetic energy)
  double inertia = 0.0;             ///< mass plus added mass [kg] (the equations of motion)
  double weight = 0.0;              ///< submerged weight, + down [N]
  double drag_area = 0.0;           ///< C_d A [m^2]
  double coupling_stiffness = 0.0;  ///< PD coupling to the anchor / ROV [N/m]
  double coupling_damping = 0.0;    ///< [N s/m]
  /// The coupling's law (forces/coupling.h) with these gains.
  LoadCoupling coupling() const { return {coupling_stiffness, coupling_damping}; }
};

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
  double fraction = 1.0;                           ///< held now (at the last ChainModel::setHoldState)
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

/// Everything about one cable that does not change during a run. Each constant is computed here, once,
/// and every pass of the dynamics reads it from here: per link in `lanes` (eight links a block, the
/// layout of the vector loops; link_block.h), per link as Eigen vectors in `properties` (the public
/// description: reports, the URDF, the paper model), and the cable-wide scalars.
class ChainModel {
 public:
  explicit ChainModel(const CableParams& params);
  /// The cable of `params` deployed as `like` is now (its first slot and its winch link's length): for
  /// live tuning, where `params` is the same cable with other fluid or coupling coefficients. Builds
  /// every constant afresh (allocates: between steps, never within one).
  ChainModel(const CableParams& params, const ChainModel& like);

  int links() const { return n_; }
  /// Per-link description; with a winch, of the cable as now deployed (the drum's slots: zero length
  /// and mass; the winch's link: its present length).
  const LinkProperties& properties() const { return properties_; }

  // The winch (docs/MODEL.md section 8): slots [0, firstLink()) are on the drum, massless and of zero
  // length; slot firstLink() is the winch's link, whose length changes with the deployed length.
  // Without a winch, firstLink() is 0 and link 0 keeps its configured length.

  /// The first deployed slot, the link at the base.
  int firstLink() const { return first_; }
  /// The block that holds it: the loops over blocks start there (the drum's blocks before it are idle).
  int firstBlock() const { return first_ / kBlockLanes; }
  /// Deploys slots [first, n): the drum's slots before it lose length and mass, the slots from it on
  /// get their configured constants, and the base's joint springs move to slot `first`. O(n); when a
  /// link is added or removed at the winch, not within an evaluation.
  void deploy(int first);
  /// Sets the length of the winch's link (slot firstLink()) [m] and every constant that follows from
  /// it. O(1); the winch calls it for each evaluation.
  void setWinchLinkLength(double length);
  /// The joints the winch has just made and the moments they hold (JointHold); at most kMaxJointHolds,
  /// the oldest dropped first. holdJoint holds `joint` with `torque` [N m] from time `start` [s] and the
  /// deployed length `deployed` [m], let go over kJointHoldLinks times `span` [m] of pay-out; it
  /// replaces a hold of the same joint.
  static constexpr int kMaxJointHolds = kJointHoldLinks + 1;
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
  StiffnessModel stiffnessModel() const { return properties_.stiffness_model; }
  Formulation formulation() const { return formulation_; }
  /// Any joint spring or damper at all (the paper model with none skips the joint torques).
  bool hasSprings() const { return has_springs_; }
  double fluidDensity() const { return fluid_density_; }  ///< [kg/m^3], 0 in air
  const LinkDrag& drag() const { return drag_; }
  /// Link k's Morison coefficients 1/2 rho C_n d and 1/2 rho C_t pi d (its section's) [kg/m^2].
  DragCoefficients dragCoefficients(int k) const {
    return {get(&LinkConstants::drag_normal, k), get(&LinkConstants::drag_tangential, k)};
  }
  /// The point attachments, ordered by link (docs/MODEL.md section 9); those of link k are
  /// [attachmentBegin(k), attachmentBegin(k + 1)).
  const std::vector<LinkAttachment>& attachments() const { return properties_.attachments; }
  int attachmentBegin(int k) const { return attachment_begin_[k]; }
  /// true when some attachment has drag (the drag pass then visits them).
  bool attachmentDrag() const { return attachment_drag_; }
  const LoadConstants& load() const { return load_; }
  /// An exact anchor (load.anchor exact) that the recursion holds by a constraint force (RK4 on the
  /// recursive formulation; docs/MODEL.md section 14): the external loads then put no coupling on the load,
  /// and solveArticulatedBody solves for the force that gives the tip the acceleration ChainData::tip_demand.
  bool heldTip() const { return held_tip_; }
  /// The time constant tau of the hold's drift correction [s] (the configured step): the tip's demanded
  /// acceleration is the target's less 2/tau the velocity error and 1/tau^2 the position error.
  double holdTimeConstant() const { return hold_time_constant_; }
  /// The stiffness of the internal hold that stands in for an exact anchor where no constraint is solved
  /// [N/m]: the implicit and semi-implicit steps fold it into their matrix (and their statics hold the tip
  /// with it, so that a run starts without a transient), and the statics of a held tip shift its target
  /// until the tip sits on the anchor. 1e6 times the cable's and load's weight in air per length of cable:
  /// a tension of the whole line's weight moves the tip by 1e-6 of the length. Stiffer, the statics' force
  /// residual meets round-off (the tip's position to 1e-16 of the length, times the hold) above their
  /// 1e-9 tolerance. 0 without an exact anchor.
  double holdStiffness() const { return hold_stiffness_; }
  /// The ROV body hung on the tip (load.mode body; inactive otherwise).
  const RovBodyConstants& body() const { return body_; }
  /// A clamped tip's bend spring and damper (forces/tip_clamp.h; inactive unless load.fixity is clamped).
  TipClamp tipClamp() const { return {properties_.tip_clamp_stiffness, properties_.tip_clamp_damping}; }
  /// The seabed and its contact's constants (disabled when the config has no seabed).
  const SeabedContactConstants& seabedContact() const { return seabed_; }
  bool hasWinch() const { return has_winch_; }
  /// Axial elasticity (cable.axial_stiffness > 0): each link stretches along its axis (its far end is
  /// l + s from its base; docs/MODEL.md section 10), and the state carries s and s' per link.
  bool axial() const { return axial_; }
  /// With axial elasticity and no mass beyond the last link's far end (no load mass, no ROV body), the
  /// last link's stretch has nothing to accelerate: it stays rigid (and carries no tension there).
  bool lastStretchLocked() const { return axial_ && last_locked_; }
  /// Link k's stretch is the locked one above.
  bool stretchLocked(int k) const { return k == n_ - 1 && lastStretchLocked(); }

  /// Per-link constants, eight links a block; lanes past the last link hold a massless link of zero length.
  int blocks() const { return static_cast<int>(lanes_.size()); }
  const LinkConstants& block(int b) const { return lanes_[b]; }
  const LinkConstants& of(int k) const { return lanes_[k / kBlockLanes]; }
  /// Scalar constant `field` of link k, e.g. get(&LinkConstants::length, k).
  double get(double (LinkConstants::*field)[kBlockLanes], int k) const { return (of(k).*field)[k % kBlockLanes]; }

 private:
  /// Slot k's lane constants and mass properties for length `length` [m] (0: on the drum).
  void setLinkLength(int k, double length);

  int n_;
  int first_ = 0;
  bool has_winch_ = false;
  bool axial_ = false;
  bool last_locked_ = false;
  bool held_tip_ = false;
  double hold_time_constant_ = 0.0, hold_stiffness_ = 0.0;
  LinkProperties nominal_;     ///< every slot as configured (the drum's at the length they will have)
  LinkProperties properties_;  ///< as deployed now
  Formulation formulation_;
  bool has_springs_;
  double fluid_density_;
  LinkDrag drag_;
  LoadConstants load_;
  RovBodyConstants body_;
  SeabedContactConstants seabed_;
  /// Per slot, the sums over its attachments: structure (m, m s, m s^2), added mass (the same moments),
  /// submerged mass (m_s, m_s s).
  struct PointSums {
    double mass0 = 0.0, mass1 = 0.0, mass2 = 0.0, added0 = 0.0, added1 = 0.0, added2 = 0.0, sub0 = 0.0, sub1 = 0.0;
  };
  std::vector<PointSums> points_;
  std::vector<int> attachment_begin_;
  bool attachment_drag_ = false;
  std::vector<LinkConstants> lanes_;  // C++17's allocator honours the 64-byte alignment
  std::array<JointHold, kMaxJointHolds> holds_{};  ///< the winch's joints made last, while held
  int hold_count_ = 0;
  void dropHold(int i);  ///< keeps the others in order
};

}  // namespace cable_dynamics
