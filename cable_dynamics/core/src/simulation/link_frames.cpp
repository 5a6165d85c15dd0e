#include "cable_dynamics/simulation/link_frames.h"

#include <algorithm>
#include <cmath>

namespace cable_dynamics {

Eigen::Quaterniond linkOrientation(const Eigen::Vector3d& axis, double sigma) {
  // Rz(-psi) Rx(-te) Rz(-phi) = [Rz(-psi) Rx(-te) Rz(psi)] Rz(-(psi + phi)): the bracket is the minimal
  // rotation carrying e_z onto u, the rest a turn about e_z by -sigma.
  const Eigen::Quaterniond swing = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis);
  return (swing * Eigen::AngleAxisd(-sigma, Eigen::Vector3d::UnitZ())).normalized();
}

void linkFrames(const Eigen::Matrix3Xd& axes, const Eigen::VectorXd& twists, const Eigen::Vector3d& base_position,
                const Eigen::VectorXd& lengths, PoseVector& links, PoseVector& after_z, PoseVector& after_x,
                Eigen::VectorXd& alpha_hint) {
  const int n = static_cast<int>(lengths.size());
  links.resize(n);
  after_z.resize(n);
  after_x.resize(n);
  Eigen::Vector3d position = base_position;
  Eigen::Quaterniond parent = Eigen::Quaterniond::Identity();
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d axis = axes.col(k).normalized();
    const Eigen::Quaterniond child = linkOrientation(axis, twists(k));
    // Relative rotation as z-x-z angles: its z column is (sin a sin b, -cos a sin b, cos b).
    const Eigen::Matrix3d relative = (parent.conjugate() * child).toRotationMatrix();
    const double beta = std::acos(std::clamp(relative(2, 2), -1.0, 1.0));
    double alpha = alpha_hint(k);
    if (std::sin(beta) > 1e-9) alpha = std::atan2(relative(0, 2), -relative(1, 2));
    alpha_hint(k) = alpha;
    const Eigen::Quaterniond z_turn = parent * Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitZ());
    const Eigen::Quaterniond x_turn = z_turn * Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitX());
    after_z[k].position = after_x[k].position = links[k].position = position;
    after_z[k].orientation = z_turn.normalized();
    after_x[k].orientation = x_turn.normalized();
    links[k].orientation = child;
    position += lengths(k) * axis;
    parent = child;
  }
}

}  // namespace cable_dynamics
