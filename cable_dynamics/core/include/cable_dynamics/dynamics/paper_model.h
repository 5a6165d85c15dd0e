#pragma once
/// \file
/// \brief The seed paper's dynamic model, generated for any number of links n by closed-form,
///        element-wise algorithms in O(n^2): M(q), h(q, q'), G(q) in the paper's coordinates.
///
/// Coordinates (3n), ordered per joint: q = [te_1, a_1, t_1, ..., te_n, a_n, t_n] with te_k the
/// elevation of link k from the downward vertical (absolute), a_k the azimuth and t_k the torsion
/// (both relative: psi_k = a_1 + ... + a_k, phi_k = t_1 + ... + t_k). Frame: base at the origin,
/// z down. See docs/MODEL.md for the derivation.

#include <cmath>

#include <Eigen/Core>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The paper's model M q'' + h + G + elastic + D q' = Q at one state, every term (sizes 3n, 3n x 3n).
struct PaperModelTerms {
  Eigen::MatrixXd M;        ///< mass matrix [kg m^2]
  Eigen::VectorXd h;        ///< Coriolis and centrifugal terms [N m]
  Eigen::VectorXd G;        ///< generalized weight (gravity minus buoyancy) [N m]
  Eigen::MatrixXd K;        ///< (tangent) stiffness [N m/rad]
  Eigen::VectorXd elastic;  ///< generalized elastic force [N m]
  Eigen::MatrixXd D;        ///< damping [N m s/rad]
  double kinetic_energy = 0.0, potential_energy = 0.0, elastic_energy = 0.0;  ///< [J]
};

/// Every term of the paper's model at (q [rad], qd [rad/s]) (allocates: for reports and services,
/// not for the step).
PaperModelTerms paperModelAt(const LinkProperties& properties, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

/// Unit axis of a link at elevation te and absolute azimuth psi (paper frame, z down) [-].
Eigen::Vector3d linkAxis(double elevation, double absolute_azimuth);

/// Unit vectors of the paper's Euler angles for a link at elevation te and absolute azimuth psi:
/// n = (cos psi, -sin psi, 0) (the elevation axis, up to sign), e = du/dte.
inline void eulerAxes(double te, double psi, Eigen::Vector3d& n, Eigen::Vector3d& e) {
  n << std::cos(psi), -std::sin(psi), 0.0;
  e << std::cos(te) * std::sin(psi), std::cos(te) * std::cos(psi), -std::sin(te);
}

/// Below this sin(te) a link counts as hanging straight down: its azimuth is not defined there.
constexpr double kVerticalSine = 1e-9;

/// Generates the inertial and gravitational terms of M q'' + h + G + (elastic) + D q' = Q.
/// Model/data split: constant parameters and the workspace are set up once in the constructor;
/// compute() does not allocate.
class PaperModel {
 public:
  explicit PaperModel(const LinkProperties& properties);

  int links() const { return n_; }
  int dof() const { return 3 * n_; }
  const LinkProperties& properties() const { return props_; }

  /// Mass matrix (3n x 3n) [kg m^2], Coriolis/centrifugal vector (3n) [N m] and generalized weight
  /// (gravity minus buoyancy, 3n) [N m] at the state (q [rad], qd [rad/s]). Outputs must be sized.
  void compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::MatrixXd& M, Eigen::VectorXd& h,
               Eigen::VectorXd& G);

  /// Potential energy of gravity minus buoyancy, zero with every link horizontal at the base height [J].
  double potentialEnergy(const Eigen::VectorXd& q) const;

  /// Joint positions in the paper frame (3 x (n+1)) [m]: column 0 the base, column k the far end of link k
  /// (column n is the terminal load).
  void linkEnds(const Eigen::VectorXd& q, Eigen::Matrix3Xd& ends) const;

  /// Centres of mass of the links in the paper frame (3 x n) [m], the seed paper's Eq. (2).
  void centresOfMass(const Eigen::VectorXd& q, Eigen::Matrix3Xd& com) const;

 private:
  int n_;
  LinkProperties props_;
  Eigen::MatrixXd mu_;       ///< (n x n) translational coupling: sum over bodies of m_b lambda_bi lambda_bj [kg m^2]
  Eigen::VectorXd gamma_;    ///< (n) weight moment l_j (ms_j/2 + outboard submerged mass) [kg m]

  // Workspace, sized once.
  Eigen::VectorXd psi_, psi_rate_, phi_rate_;
  Eigen::Matrix3Xd u_, e_, w_, accel_velocity_;
  Eigen::MatrixXd block_te_te_, block_te_psi_, block_psi_psi_;
  Eigen::VectorXd h_te_, h_psi_, h_phi_;
  Eigen::VectorXd polar_cos_suffix_, polar_suffix_;  ///< sum_{i>=k} I_P,i cos te_i and sum_{i>=k} I_P,i
};

}  // namespace cable_dynamics
