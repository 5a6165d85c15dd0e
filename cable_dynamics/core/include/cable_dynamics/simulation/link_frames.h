#pragma once
/// \file
/// \brief Poses of every link in the paper frame, for TF and the URDF: each link's frame has its origin at
///        the link's base end and its z axis along the link (base end to far end).

#include <vector>

#include <Eigen/Geometry>
#include <Eigen/StdVector>

#include <Eigen/Core>

namespace cable_dynamics {

/// A rigid pose: position [m] and orientation.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};
using PoseVector = std::vector<Pose, Eigen::aligned_allocator<Pose>>;

/// Orientation of a link from its axis u and its twist sigma = psi + phi about the vertical: the paper's
/// Rz(-psi) Rx(-te) Rz(-phi) written without psi and phi apart, as the minimal rotation from the
/// vertical onto u after a turn by -sigma about the vertical (singular only for u straight up).
Eigen::Quaterniond linkOrientation(const Eigen::Vector3d& axis, double sigma);

/// Each link's frame and, between neighbours, the two intermediate frames of the URDF's three revolute
/// joints (about z, x, z: R_{k-1}^T R_k = Rz(alpha) Rx(beta) Rz(gamma)). `links` gets n poses, `after_z`
/// and `after_x` the intermediate ones (paper frame, at the link's base end). `alpha_hint` (n) keeps
/// alpha continuous where beta = 0 leaves it free, and is updated. `axes` (3 x n) are the links' unit
/// axes, `twists` (n) their twists sigma [rad], `lengths` (n) [m] (SimulationSnapshot and LinkProperties).
void linkFrames(const Eigen::Matrix3Xd& axes, const Eigen::VectorXd& twists, const Eigen::Vector3d& base_position,
                const Eigen::VectorXd& lengths, PoseVector& links, PoseVector& after_z, PoseVector& after_x,
                Eigen::VectorXd& alpha_hint);

}  // namespace cable_dynamics
