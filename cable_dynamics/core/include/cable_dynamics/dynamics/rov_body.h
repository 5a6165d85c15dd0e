#pragma once
/// \file
/// \brief The ROV of load.mode body: a 6-DOF rigid body in Fossen's form hung on the cable's tip by a ball
///        joint at its attachment point P, so that the cable and the body are one articulated system and
///        every integrator steps them together (no exchange, no coupling spring).
///
/// Fossen (Handbook of Marine Craft Hydrodynamics and Motion Control, 2011, eqs. 6.1-6.6, 7.190), in the
/// body frame about its origin O, with nu = (v, w) and nu_r = nu - (R^T v_c, 0) relative to the current:
///   (M_RB + M_A) nu' + C_RB(nu) nu + C_A(nu_r) nu_r + D(nu_r) nu_r + g(eta) = tau + tau_cable
/// with C(nu) nu = (w x p1, v x p1 + w x p2), p = M nu (Fossen's eq. 6.43 for any symmetric M), D the
/// linear plus quadratic diagonal damping, g the weight at the centre of gravity and the buoyancy at the
/// centre of buoyancy. A uniform current turns in the body frame: M_A nu_r' = M_A nu' + M_A (w x v_cb, 0).
///
/// About P (nu_O = H nu_P, H = [I S(r); 0 I], r = the attachment from O) the mass matrix is
/// M_P = H^T M H = [A B; B^T C] and the forces f_P = H^T f_O. The cable's force on the body acts at P and
/// has no moment about it, so the rotation follows from the tip's acceleration a (paper frame):
///   a_P = R^T a - w x v_P,  w' = C^-1 (f_P,rot - B^T a_P),
/// and the tip carries the body as a 3x3 mass and a bias force (paper frame):
///   J = R S R^T a + R (B C^-1 f_P,rot - f_P,trans - S (w x v_P)),  S = A - B C^-1 B^T,
/// J being the cable's force on the body. The articulated-body recursions start from (R S R^T, J at a = the
/// known acceleration) instead of a point load's (m I, m a - F).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// The body's constants (body frame, about O unless stated); inactive unless load.mode is body.
struct RovBodyConstants {
  bool active = false;
  double mass = 0.0;                     ///< in air [kg]
  Matrix6d rigid_mass = Matrix6d::Zero();  ///< M_RB about O, with the centre of gravity's offset [kg, kg m, kg m^2]
  Matrix6d added_mass = Matrix6d::Zero();  ///< M_A about O
  Vector6d linear_damping = Vector6d::Zero(), quadratic_damping = Vector6d::Zero();
  double weight = 0.0;    ///< m g [N]
  double buoyancy = 0.0;  ///< rho V g [N]
  Eigen::Vector3d center_of_gravity = Eigen::Vector3d::Zero(), center_of_buoyancy = Eigen::Vector3d::Zero();
  Eigen::Vector3d attachment = Eigen::Vector3d::Zero();  ///< P from O [m]
  Eigen::Vector4d initial_attitude = Eigen::Vector4d(0.0, 1.0, 0.0, 0.0);  ///< paper from body at start (w, x, y, z)
  // About P: M_P = [A B; B^T C]; S = A - B C^-1 B^T [kg], B C^-1 [m^-1 ...], C^-1, B^T.
  Eigen::Matrix3d schur = Eigen::Matrix3d::Zero(), b_c_inverse = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d c_inverse = Eigen::Matrix3d::Zero(), b_transpose = Eigen::Matrix3d::Zero();

  /// From load.mass, load.volume, load.attachment and load.body (validated by the gate), in a fluid of
  /// `fluid_density` [kg/m^3] under `gravity` [m/s^2].
  static RovBodyConstants make(const LoadParams& load, double fluid_density, double gravity);
};

/// The body's part of one evaluation (ChainData::body).
struct RovBodyTerms {
  Eigen::Vector4d attitude = Eigen::Vector4d(1.0, 0.0, 0.0, 0.0);  ///< the state's quaternion (w, x, y, z)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< paper frame from body frame
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();         ///< body frame [rad/s]
  Eigen::Vector3d attach_velocity = Eigen::Vector3d::Zero();  ///< v_P, body frame [m/s]
  Vector6d velocity = Vector6d::Zero();  ///< nu at O, body frame [m/s, rad/s]
  Vector6d thrust = Vector6d::Zero();    ///< tau at O, body frame [N, N m]
  Vector6d fluid = Vector6d::Zero();     ///< the fluid's forces at O but the added mass's M_A nu' [N, N m]
  Vector6d force = Vector6d::Zero();     ///< f_P: everything on the body but the cable and the inertia, about P
  Eigen::Matrix3d tip_mass = Eigen::Matrix3d::Zero();  ///< R S R^T [kg] (paper)
  Eigen::Vector3d tip_bias = Eigen::Vector3d::Zero();  ///< J at zero tip acceleration [N] (paper)
  // After the solve:
  Vector6d acceleration = Vector6d::Zero();  ///< nu' at O, body frame [m/s^2, rad/s^2]
  double thrust_power = 0.0;  ///< tau . nu [W]
  double fluid_power = 0.0;   ///< the fluid's forces (added mass, damping) . nu, <= 0 in still water [W]
};

/// The body's terms at its attitude `attitude` (paper from body, unit quaternion w, x, y, z) and angular
/// velocity `omega` (body frame), its attachment moving at `tip_velocity` (paper) in a current `current`
/// (paper) under the thrust `thrust` (body frame, at O). O(1), no allocation.
void computeRovBodyTerms(const RovBodyConstants& body, const Eigen::Vector4d& attitude, const Eigen::Vector3d& omega,
                         const Eigen::Vector3d& tip_velocity, const Eigen::Vector3d& current, const Vector6d& thrust,
                         RovBodyTerms& terms);

/// After the solve, from the tip's acceleration (paper): the body's accelerations and powers. Returns the
/// cable's force on the body (paper) [N].
Eigen::Vector3d finishRovBody(const RovBodyConstants& body, const Eigen::Vector3d& tip_acceleration, RovBodyTerms& terms);

/// The attitude's rate q' = q (0, w) / 2 (w, x, y, z; body-frame w).
Eigen::Vector4d attitudeRate(const Eigen::Vector4d& attitude, const Eigen::Vector3d& omega);

/// The attitude q turned by the body-frame rotation vector `turn` [rad]: q exp(turn), exactly, normalized.
Eigen::Vector4d turnedAttitude(const Eigen::Vector4d& attitude, const Eigen::Vector3d& turn);

/// Rotation matrix of a unit quaternion (w, x, y, z).
Eigen::Matrix3d rotationOf(const Eigen::Vector4d& attitude);

/// The body's kinetic energy 1/2 nu^T M_RB nu (the added mass's is the fluid's, as for the links) and
/// its potential energy, weight at the centre of gravity less buoyancy at the centre of buoyancy, zero at
/// the base's rest height, with its attachment at `tip_position` (paper, z down) [J].
void rovBodyEnergy(const RovBodyConstants& body, const RovBodyTerms& terms, const Eigen::Vector3d& tip_position,
                   double& kinetic, double& potential);

/// The body's origin O (paper) with its attachment at `tip_position`.
Eigen::Vector3d rovBodyOrigin(const RovBodyConstants& body, const Eigen::Matrix3d& rotation,
                              const Eigen::Vector3d& tip_position);

}  // namespace cable_dynamics
