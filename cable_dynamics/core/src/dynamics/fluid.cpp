#include "cable_dynamics/dynamics/fluid.h"

#include <cassert>
#include <cmath>
#include <stdexcept>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {

CurrentField::CurrentField(const FluidParams& fluid) : uniform_(worldToPaper(fluid.current)) {
  const int rows = static_cast<int>(fluid.current_profile.size());
  depth_.resize(rows);
  profile_.resize(3, rows);
  for (int i = 0; i < rows; ++i) {
    depth_(i) = fluid.current_profile[i](0);
    profile_.col(i) = worldToPaper(fluid.current_profile[i].tail<3>());
  }
}

void CurrentField::setUniformWorld(const Eigen::Vector3d& current_world) {
  uniform_ = worldToPaper(current_world);
  depth_.resize(0);
  profile_.resize(3, 0);
}

Eigen::Vector3d CurrentField::at(double z) const {
  const int rows = static_cast<int>(depth_.size());
  if (rows == 0) return uniform_;
  if (z <= depth_(0)) return profile_.col(0);
  if (z >= depth_(rows - 1)) return profile_.col(rows - 1);
  int i = 1;
  while (depth_(i) < z) ++i;  // profiles are short: a linear scan beats a search
  const double f = (z - depth_(i - 1)) / (depth_(i) - depth_(i - 1));
  return (1.0 - f) * profile_.col(i - 1) + f * profile_.col(i);
}

Eigen::Vector3d morisonDragPerLength(const Eigen::Vector3d& axis, const Eigen::Vector3d& velocity,
                                     const Eigen::Vector3d& current, double density, double diameter,
                                     double drag_normal, double drag_tangential) {
  const Eigen::Vector3d relative = current - velocity;  // water relative to the cable
  const Eigen::Vector3d tangential = relative.dot(axis) * axis;
  const Eigen::Vector3d normal = relative - tangential;
  return 0.5 * density * diameter *
         (drag_normal * normal.norm() * normal + drag_tangential * M_PI * tangential.norm() * tangential);
}

void gaussLegendreUnit(int points, double* nodes, double* weights) {
  // Nodes and weights on [-1, 1] (Abramowitz and Stegun, table 25.4), mapped to [0, 1].
  static const double kNodes[8][4] = {
      {0.0, 0, 0, 0},
      {0.5773502691896257645, 0, 0, 0},
      {0.0, 0.7745966692414833770, 0, 0},
      {0.3399810435848562648, 0.8611363115940525752, 0, 0},
      {0.0, 0.5384693101056830910, 0.9061798459386639928, 0},
      {0.2386191860831969086, 0.6612093864662645136, 0.9324695142031520278, 0},
      {0.0, 0.4058451513773971669, 0.7415311855993944399, 0.9491079123427585245},
      {0.1834346424956498049, 0.5255324099163289858, 0.7966664774136267396, 0.9602898564975362317}};
  static const double kWeights[8][4] = {
      {2.0, 0, 0, 0},
      {1.0, 0, 0, 0},
      {0.8888888888888888889, 0.5555555555555555556, 0, 0},
      {0.6521451548625461427, 0.3478548451374538574, 0, 0},
      {0.5688888888888888889, 0.4786286704993664680, 0.2369268850561890875, 0},
      {0.4679139345726910473, 0.3607615730481386076, 0.1713244923791703450, 0},
      {0.4179591836734693878, 0.3818300505051189449, 0.2797053914892766679, 0.1294849661688696933},
      {0.3626837833783619830, 0.3137066458778872873, 0.2223810344533744706, 0.1012285362903762592}};
  if (points < 1 || points > 8) throw std::invalid_argument("gaussLegendreUnit: points must be 1..8");
  const int row = points - 1;
  int out = 0;
  // Odd counts have a centre node (stored first), then symmetric pairs.
  const bool odd = points % 2 == 1;
  if (odd) {
    nodes[out] = 0.5;
    weights[out++] = 0.5 * kWeights[row][0];
  }
  for (int i = odd ? 1 : 0; out < points; ++i) {
    const double x = kNodes[row][i], w = 0.5 * kWeights[row][i];
    nodes[out] = 0.5 * (1.0 - x);
    weights[out++] = w;
    nodes[out] = 0.5 * (1.0 + x);
    weights[out++] = w;
  }
  assert(out == points);
}

LinkDrag::LinkDrag(const FluidParams& fluid) : points_(fluid.drag_points) { gaussLegendreUnit(points_, nodes_, weights_); }

void LinkDrag::pointwise(const CurrentField& current, double l, const DragCoefficients& coefficients,
                         const Eigen::Vector3d& base, const Eigen::Vector3d& velocity, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& axis_rate, Eigen::Vector3d& force, Eigen::Vector3d& moment) const {
  force.setZero();
  moment.setZero();
  for (int i = 0; i < points_; ++i) {
    const double s = nodes_[i] * l, w = weights_[i] * l;
    const Eigen::Vector3d relative = current.at(base.z() + s * axis.z()) - (velocity + s * axis_rate);
    const Eigen::Vector3d tangential = relative.dot(axis) * axis, normal = relative - tangential;
    const Eigen::Vector3d drag =
        coefficients.normal * normal.norm() * normal + coefficients.tangential * tangential.norm() * tangential;
    force += w * drag;
    moment += (w * s) * drag;
  }
}

}  // namespace cable_dynamics
