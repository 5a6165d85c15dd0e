#pragma once
/// \file
/// \brief The chain's constants, built once per cable from its parameters and never changed after: the
///        "model" half of the model/data split (ChainData holds everything that changes, the deployment
///        the winch changes included). Every method is const; live tuning replaces the whole model
///        between steps (CableSimulator::retune) and redeploys the data's cable with it.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_deployment.h"
#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/fold_stop.h"
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

/// Everything about one cable that does not change during a run. Each constant is computed here, once,
/// and every pass of the dynamics reads it from here: per link in `lanes` (eight links a block, the
/// layout of the vector loops; link_block.h), per link as Eigen vectors in `properties` (the public
/// description: reports, the URDF, the paper model), and the cable-wide scalars.
class ChainModel {
 public:
  /// From the configured parameters (or the model's copy: withDrumSlots is applied once).
  explicit ChainModel(const CableParams& params);

  /// The parameters as the model uses them: with a winch, `configured` with the drum's
  /// winch.stored_links slots in front of the configured cable (links, link_lengths, initial.*; each slot
  /// of the base link's configured length, straight down and at rest) and winch.slots_built set. Without a
  /// winch, or when the slots are already built, `configured` as it is.
  static CableParams withDrumSlots(const CableParams& configured);
  /// Whether a stretching link of these params carries half of its mass at its far end beyond its stretch
  /// (docs/MODEL.md section 12): yes but with a winch, whose link changes its mass as it pays out.
  static bool farPoints(const CableParams& params) { return !params.winch.enabled; }

  int links() const { return n_; }
  /// Per-link description of every slot as configured (a winch's drum slots at the length they will have
  /// when deployed). The cable as deployed now is ChainDeployment::properties().
  const LinkProperties& configured() const { return nominal_; }

  // The winch (docs/MODEL.md section 8): slots [0, first) are on the drum, massless and of zero length;
  // slot first is the winch's link, whose length changes with the deployed length. Without a winch the
  // first slot is 0 and link 0 keeps its configured length. The model writes the deployment it describes
  // (ChainData::deployed); nothing else does.

  /// The deployment at the start: the configured cable, with winch.stored_links slots on the drum.
  ChainDeployment initialDeployment() const;
  /// Deploys slots [first, n) in `d`: the drum's slots before it lose length and mass, the slots from it
  /// on get their configured constants, the base's joint springs move to slot `first`, and a held joint
  /// at or before it is dropped. O(n); when a link is added or removed at the winch, not within an
  /// evaluation. No allocation.
  void deploy(ChainDeployment& d, int first) const;
  /// Sets the length of `d`'s winch link (slot d.firstLink()) [m] and every constant that follows from
  /// it. O(1); every evaluation with a winch calls it.
  void setWinchLinkLength(ChainDeployment& d, double length) const;
  /// `d`'s constants rebuilt from this model, keeping its first slot, its winch link's length and its
  /// joint holds: live tuning's new coefficients on the running deployment.
  void redeploy(ChainDeployment& d) const;
  StiffnessModel stiffnessModel() const { return nominal_.stiffness_model; }
  Formulation formulation() const { return formulation_; }
  /// Any joint spring or damper at all (the paper model with none skips the joint torques).
  bool hasSprings() const { return has_springs_; }
  double fluidDensity() const { return fluid_density_; }  ///< [kg/m^3], 0 in air
  const LinkDrag& drag() const { return drag_; }
  /// The point attachments, ordered by link (docs/MODEL.md section 9); those of link k are
  /// [attachmentBegin(k), attachmentBegin(k + 1)).
  const std::vector<LinkAttachment>& attachments() const { return nominal_.attachments; }
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
  /// The hanging tension that sizes the joints' fold stops (forces/fold_stop.h) [N]: g times the
  /// magnitudes of the submerged masses of every slot as configured, its attachments and the load.
  double foldStopTension() const { return fold_stop_tension_; }
  /// The fold stop of joint k (between slots k-1 and k, k >= 1) at the lengths of `p` (a deployment's).
  FoldStop foldStop(const LinkProperties& p, int k) const { return FoldStop::ofJoint(p, k, fold_stop_tension_); }
  /// A clamped tip's bend spring and damper (forces/tip_clamp.h; inactive unless load.fixity is clamped).
  TipClamp tipClamp() const { return {nominal_.tip_clamp_stiffness, nominal_.tip_clamp_damping}; }
  /// The seabed and its contact's constants (disabled when the config has no seabed).
  const SeabedContactConstants& seabedContact() const { return seabed_; }
  bool hasWinch() const { return has_winch_; }
  /// Axial elasticity (cable.axial_stiffness > 0): each link stretches along its axis (its far end is
  /// l + s from its base; docs/MODEL.md section 10), and the state carries s and s' per link.
  bool axial() const { return axial_; }
  /// The stretching links carry far-end points (axial elasticity and farPoints(params)).
  bool farEndPoints() const { return axial_ && far_points_; }
  /// With axial elasticity and no mass beyond the last link's far end (no load mass, no ROV body), the
  /// last link's stretch has nothing to accelerate: it stays rigid (and carries no tension there).
  bool lastStretchLocked() const { return axial_ && last_locked_; }
  /// Link k's stretch is the locked one above.
  bool stretchLocked(int k) const { return k == n_ - 1 && lastStretchLocked(); }

 private:
  /// The constructor proper, from parameters with the drum's slots built (withDrumSlots).
  ChainModel(const CableParams& params, int slots_built);
  /// Slot k's lane constants and mass properties in `d` for length `length` [m] (0: on the drum).
  void setLinkLength(ChainDeployment& d, int k, double length) const;

  int n_;
  int initial_first_ = 0;  ///< winch.stored_links
  bool has_winch_ = false;
  bool far_points_ = false;  ///< farPoints(params)
  bool axial_ = false;
  bool last_locked_ = false;
  bool held_tip_ = false;
  double hold_time_constant_ = 0.0, hold_stiffness_ = 0.0;
  double fold_stop_tension_ = 0.0;
  LinkProperties nominal_;  ///< every slot as configured (the drum's at the length they will have)
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
};

}  // namespace cable_dynamics
