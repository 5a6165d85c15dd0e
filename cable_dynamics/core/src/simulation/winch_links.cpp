#include "cable_dynamics/simulation/winch_links.h"

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {
namespace {

/// A slot on the drum: along the vertical, untwisted, at rest (the kinematics normalize its axis).
void stow(Eigen::VectorXd& x, int k) {
  x.segment<3>(StateLayout::axis(k)) = Eigen::Vector3d::UnitZ();
  x(StateLayout::twist(k)) = 0.0;
  x.segment<3>(StateLayout::omega(k)).setZero();
}

}  // namespace

WinchRegrid winchRegridDue(const ChainDeployment& deployed, double winch_length, double link_length) {
  const int first = deployed.firstLink(), n = static_cast<int>(deployed.properties().length.size());
  if (winch_length > kWinchLinkSplitAt * link_length && first > 0) return WinchRegrid::kAdded;
  if (winch_length < kWinchLinkMergeAt * link_length && first + 1 < n) return WinchRegrid::kRemoved;
  return WinchRegrid::kNone;
}

WinchRegrid regridWinchLinks(ChainDynamics& dynamics, Eigen::VectorXd& x, double winch_length, double link_length,
                             double winch_speed, double& outboard_length) {
  const int first = dynamics.deployed().firstLink();
  const WinchRegrid due = winchRegridDue(dynamics.deployed(), winch_length, link_length);
  if (due == WinchRegrid::kAdded) {
    // The new winch's link (slot first - 1) is the inboard part of the old one: same axis, twist and
    // angular velocity, so every material point keeps its position and velocity.
    const int fresh = first - 1;
    x.segment<StateLayout::kPerLink>(StateLayout::axis(fresh)) = x.segment<StateLayout::kPerLink>(StateLayout::axis(first));
    dynamics.data().azimuths.copy(first, fresh);
    dynamics.deploy(fresh);  // slot `first` is a configured link again, of its configured length
    outboard_length += dynamics.properties().length(first);
    return WinchRegrid::kAdded;
  }
  if (due == WinchRegrid::kRemoved) {
    const int next = first + 1;
    const double a = winch_length, b = dynamics.properties().length(next), total = a + b;
    const Eigen::Vector3d u_a = x.segment<3>(StateLayout::axis(first)).normalized();
    const Eigen::Vector3d u_b = x.segment<3>(StateLayout::axis(next)).normalized();
    const Eigen::Vector3d w_a = x.segment<3>(StateLayout::omega(first)), w_b = x.segment<3>(StateLayout::omega(next));
    const Eigen::Vector3d u = (a * u_a + b * u_b).normalized();
    // The far end's velocity relative to the base's (the base's own motion is the same before and
    // after): v u_a + a u_a' + b u_b' before, v u + L u' after, for the pay-out speed v.
    const Eigen::Vector3d far = winch_speed * u_a + a * w_a.cross(u_a) + b * w_b.cross(u_b);
    const Eigen::Vector3d rate = (far - winch_speed * u - u.dot(far - winch_speed * u) * u) / total;  // u'
    const double spin = (a * w_a.dot(u_a) + b * w_b.dot(u_b)) / total;  // the mean spin, by mass
    x.segment<3>(StateLayout::axis(next)) = u;
    x.segment<3>(StateLayout::omega(next)) = u.cross(rate) + spin * u;
    stow(x, first);
    dynamics.deploy(next);
    outboard_length -= b;
    return WinchRegrid::kRemoved;
  }
  return WinchRegrid::kNone;
}

}  // namespace cable_dynamics
