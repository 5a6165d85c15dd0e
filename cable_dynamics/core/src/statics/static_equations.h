#pragma once
// The equilibrium equations of the deployed links, one link at a time (static_solver.h states them):
// the solver's Jacobian is differenced link by link, so every residual reads only its link and the
// two neighbours. Internal to the statics.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/statics/static_solver.h"

namespace cable_dynamics {
namespace statics {

/// The unknowns of the deployed links i = 0 .. m-1 (link first_link + i), paper frame.
struct StaticState {
  Eigen::Matrix3Xd axis;   ///< (3 x m) unit axes u_i
  Eigen::Matrix3Xd force;  ///< (3 x m) J_i, the force on the outboard part at link i's base end [N]
  Eigen::Matrix3Xd base;   ///< (3 x m) base ends p_i [m]
  void resize(int m) {
    axis.resize(3, m);
    force.resize(3, m);
    base.resize(3, m);
  }
};

/// One link's residuals, unscaled.
struct LinkResidual {
  Eigen::Vector3d force;    ///< J_i - J_{i+1} + F_i [N]
  Eigen::Vector3d moment;   ///< u_i x (N_i - l_i J_{i+1}) + tau_i, normal to u_i [N m]
  Eigen::Vector3d closure;  ///< p_i - p_{i-1} - l_{i-1} u_{i-1} [m]
};

/// The spring an exact anchor's statics hold the tip with while solveStatics shifts its target onto the
/// anchor [N/m]: 1e-4 of the dynamics' internal hold (ChainModel::holdStiffness), 100 times the line's
/// weight per length. Stiffer holds slowed Newton on stiff cables (1e-2: 3530 iterations a sweep where
/// this takes 9, the stiff anchored case of test_statics) and stalled the seabed's contact continuation
/// (1e0 on the mooring chain); Broyden's shifts make up for a hold softer than the line.
inline double staticHoldStiffness(const ChainModel& model) { return 1e-4 * model.holdStiffness(); }

class StaticEquations {
 public:
  StaticEquations(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                  const StaticProblem& problem);

  int links() const { return m_; }                      ///< deployed links m
  int link(int i) const { return first_ + i; }          ///< model index of deployed link i
  double length(int i) const { return length_(i); }     ///< [m]
  double deployedLength() const { return length_.sum(); }  ///< [m]
  const StaticProblem& problem() const { return problem_; }
  bool hasBendSprings() const { return has_bend_; }
  bool uniformCurrent() const { return current_.uniform(); }

  /// Multiplies every bend spring (continuation on the stiffness; 1 = the model's).
  void setStiffnessScale(double scale) { stiffness_scale_ = scale; }
  /// Multiplies the seabed's contact springs (continuation from a cable hanging through the bed; 1 = the
  /// model's, 0 = no seabed).
  void setContactScale(double scale) { contact_scale_ = scale; }
  bool hasSeabed() const { return model_.seabedContact().enabled(); }
  /// true when some contact point of the deployed links or the load is in the bed at s.
  bool touchesSeabed(const StaticState& s) const;

  /// Weight and drag at rest on deployed link i with axis u and base end p: force F [N] and its first
  /// moment about the base end N [N m], as computeExternalLoads applies them at zero velocity.
  void linkLoads(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p, Eigen::Vector3d& force,
                 Eigen::Vector3d& moment) const;
  /// The far half of deployed link i's skin friction in the current, on its far-end point at rest
  /// (docs/MODEL.md section 12; computeExternalLoads at zero velocity); 0 without a far-end point [N].
  double farDrag(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p) const;
  /// The load's weight, drag and seabed contact at rest at tip position `tip` [m] (no coupling) [N].
  Eigen::Vector3d loadForceFree(const Eigen::Vector3d& tip) const;
  /// The coupling spring's force on the load at `tip` [N] (zero when the tip is free).
  Eigen::Vector3d couplingForce(const Eigen::Vector3d& tip) const;
  double couplingStiffness() const { return coupling_stiffness_; }  ///< [N/m]

  /// The tip, p_{m-1} + l u_{m-1} [m].
  Eigen::Vector3d tip(const StaticState& s) const {
    return s.base.col(m_ - 1) + length_(m_ - 1) * s.axis.col(m_ - 1);
  }
  /// J_{i+1} for i < m-1, and at the last link minus the load's external force [N].
  Eigen::Vector3d outboardForce(const StaticState& s, int i) const;

  /// Bend spring torque of joint i (between deployed link i-1, or the clamp for i = 0, and link i) on
  /// link i [N m]; link i-1 gets its opposite.
  Eigen::Vector3d bendTorque(int i, const Eigen::Vector3d& prev, const Eigen::Vector3d& axis) const;
  /// The clamp's axis, paper frame [-].
  const Eigen::Vector3d& clampAxis() const { return clamp_axis_; }

  void residual(const StaticState& s, int i, LinkResidual& r) const;

 private:
  /// The seabed's springs on deployed link i at rest (seabed_contact.cpp's points), added to its force
  /// and first moment.
  void addSeabedContact(int i, const Eigen::Vector3d& u, const Eigen::Vector3d& p, Eigen::Vector3d& force,
                        Eigen::Vector3d& moment) const;

 public:

  /// F, the sum of the magnitudes of every external force at s [N] (static_solver.h), at least 1e-9 N.
  double forceScale(const StaticState& s) const;

 private:
  const ChainModel& model_;
  const ChainDeployment& deployed_;  ///< the cable as deployed (a winch's link at its present length)
  const CurrentField& current_;
  StaticProblem problem_;
  int first_, m_;
  Eigen::VectorXd length_;          ///< (m) [m]
  Eigen::VectorXd weight_;          ///< (m) submerged weight with the far-end point's, + down [N]
  Eigen::VectorXd weight_moment_;   ///< (m) its first moment about the base end, along the axis [N m]
  Eigen::VectorXd bend_stiffness_;  ///< (m) joint i's k_b [N m/rad]
  Eigen::VectorXd fold_diameter_;   ///< (m) the larger outer diameter of joint i's two links [m] (its fold stop)
  double fold_tension_ = 0.0;       ///< the fold stops' hanging tension [N] (ChainModel::foldStopTension); 0: none
  bool has_bend_, in_water_;
  double coupling_stiffness_;       ///< [N/m], 0 when the tip is free
  double stiffness_scale_ = 1.0;
  double contact_scale_ = 1.0;
  Eigen::Vector3d clamp_axis_;
  double tip_clamp_stiffness_ = 0.0;  ///< [N m/rad], 0 with a pinned tip
  Eigen::Vector3d tip_clamp_axis_;
};

}  // namespace statics
}  // namespace cable_dynamics
