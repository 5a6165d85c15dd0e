#pragma once
/// \file
/// \brief Springs and dampers of the fictitious joints: the paper's diagonal K and D on the generalized
///        coordinates, or a geometrically consistent bending/twist energy between neighbouring links.

#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/forces/fold_stop.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// Elastic energy V_e(q), its gradient (the generalized elastic force, "K q" in the paper's form)
/// and its Hessian (the tangent stiffness K), plus the joint damping matrix D.
///
/// - Paper model: V_e = 1/2 q^T K q with K = diag(k_e, k_a, k_t) per joint.
/// - Bending model: for joint k between link k-1 (the base clamp, LinkProperties::clamp_axis, for k = 1) and
///   link k, V_e = 1/2 k_b beta_k^2 + 1/2 k_t tau_k^2, with beta_k the angle between the two link axes
///   and tau_k the twist of link k relative to link k-1 carried over by parallel transport (the discrete
///   rod twist). k_b is the elevation spring, k_t the torsion spring. Both are invariant to a rigid
///   rotation of the cable about the vertical and free of the zero-elevation singularity.
/// - Damping, both models: D = diag(c_e, c_a, c_t) on the generalized coordinates (the paper's form).
class ElasticJoints {
 public:
  explicit ElasticJoints(const LinkProperties& properties);

  /// Elastic energy [J] at q [rad].
  double energy(const Eigen::VectorXd& q) const;

  /// Generalized elastic force dV_e/dq (3n) [N m]; added to the left-hand side of the equations.
  void force(const Eigen::VectorXd& q, Eigen::VectorXd& out) const;

  /// Tangent stiffness d^2 V_e / dq^2 (3n x 3n) [N m/rad]; the constant diagonal K for the paper model.
  void stiffness(const Eigen::VectorXd& q, Eigen::MatrixXd& out) const;

  /// Damping matrix D (3n x 3n) [N m s/rad].
  void damping(Eigen::MatrixXd& out) const;

  /// Bend angle beta_k [rad] and twist tau_k [rad] of joint k (0-based) for the bending model.
  void bendAndTwist(const Eigen::VectorXd& q, int joint, double& bend, double& twist) const;

 private:
  int n_;
  StiffnessModel model_;
  Eigen::VectorXd k_diag_;  ///< (3n) paper springs in coordinate order [N m/rad]
  Eigen::VectorXd c_diag_;  ///< (3n) dampers in coordinate order [N m s/rad]
  double clamp_elevation_;  ///< of the base clamp's axis [rad]
  double clamp_azimuth_;    ///< of the base clamp's axis [rad]
  std::vector<FoldStop> stops_;  ///< (n) joint k's fold stop (bending model, k >= 1; forces/fold_stop.h)

  /// Local variable i (te_prev, te, a, t) of joint k, with the clamp standing in for link 0.
  double local(const Eigen::VectorXd& q, int k, int i) const;
};

}  // namespace cable_dynamics
