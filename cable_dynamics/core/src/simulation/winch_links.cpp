#include "cable_dynamics/simulation/winch_links.h"

#include <algorithm>

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

/// The stretch entries of the state (axial elasticity; none with rigid links).
struct StretchSlots {
  explicit StretchSlots(const ChainModel& model)
      : axial(model.axial()), n(model.links()), body(model.body().active) {}
  double value(const Eigen::VectorXd& x, int k) const { return axial ? x(StateLayout::stretch(n, body, k)) : 0.0; }
  double rate(const Eigen::VectorXd& x, int k) const { return axial ? x(StateLayout::stretchRate(n, body, k)) : 0.0; }
  void set(Eigen::VectorXd& x, int k, double s, double s_rate) const {
    x(StateLayout::stretch(n, body, k)) = s;
    x(StateLayout::stretchRate(n, body, k)) = s_rate;
  }
  bool axial;
  int n;
  bool body;
};

/// Splits the winch's link `first` of unstretched length `winch_length` [m] into the new winch's link
/// (first - 1, the inboard part) and slot `first` of `configured` length [m], keeping its strain
/// eps = s / l and its strain rate: the configured part takes s = eps l_c, s' = eps' l_c; the winch's part
/// the rest, s' = eps' l_a + eps v, for it grows at the pay-out speed v [m/s].
/// A link's stretch carries the tension at its far end (its own weight rides with its base end: docs/MODEL.md
/// section 12), so the winch's part, whose far end now carries the configured part's weight along the axis
/// too, w l_c u.g, stretches by that over its EA / l_a more while the line is taut: the tension goes on
/// through the split (without it, the line pull of a 1 m-link line, EA 1e6 N, dipped 0.25 % at each one),
/// and the far end moves out by w l_c l_a u.g / EA (7e-6 m there), what the finer lumping puts there.
void splitStretch(const ChainModel& model, const LinkProperties& properties, Eigen::VectorXd& x, int first,
                  double winch_length, double configured, double winch_speed) {
  const StretchSlots stretch(model);
  const double s = stretch.value(x, first), rate = stretch.rate(x, first);
  const double strain = s / winch_length;
  const double strain_rate = (rate - strain * winch_speed) / winch_length;  // d/dt (s / l), l' = v
  const double inboard = winch_length - configured;
  const double down = x.segment<3>(StateLayout::axis(first)).normalized().z();  // u.g / |g|: z is down
  const double weight_along = properties.gravity * properties.submerged_mass(first) * down;  // [N], l_c's
  // (Less where the line rises from the drum or floats: never below slack.)
  const double inboard_stretch = s > 0.0 ? std::max(0.0, strain * inboard + weight_along * inboard / properties.axial_stiffness(first))
                                         : strain * inboard;
  stretch.set(x, first - 1, inboard_stretch, strain_rate * inboard + strain * winch_speed);
  stretch.set(x, first, strain * configured, strain_rate * configured);
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
    const double configured = dynamics.properties().length(first);
    if (dynamics.model().axial()) {
      splitStretch(dynamics.model(), dynamics.properties(), x, first, winch_length, configured, winch_speed);
    }
    outboard_length += configured;
    return WinchRegrid::kAdded;
  }
  if (due == WinchRegrid::kRemoved) {
    const int next = first + 1;
    const double a = winch_length, b = dynamics.properties().length(next), total = a + b;
    // With axial elasticity each link's far end is l + s along its axis (s, s': 0 with rigid links).
    const StretchSlots stretch(dynamics.model());
    const double s_a = stretch.value(x, first), s_b = stretch.value(x, next);
    const double r_a = stretch.rate(x, first), r_b = stretch.rate(x, next);
    const Eigen::Vector3d u_a = x.segment<3>(StateLayout::axis(first)).normalized();
    const Eigen::Vector3d u_b = x.segment<3>(StateLayout::axis(next)).normalized();
    const Eigen::Vector3d w_a = x.segment<3>(StateLayout::omega(first)), w_b = x.segment<3>(StateLayout::omega(next));
    const Eigen::Vector3d chord = (a + s_a) * u_a + (b + s_b) * u_b;
    const Eigen::Vector3d u = chord.normalized();
    // The far end's velocity relative to the base's (the base's own motion is the same before and
    // after): v u_a + s_a' u_a + (a + s_a) u_a' + s_b' u_b + (b + s_b) u_b' before, v u + s' u + (L + s) u'
    // after, for the pay-out speed v. A stretching link keeps the far end's position and velocity (s is
    // the chord's excess over L, s' the velocity along it); a rigid one keeps what is across its axis.
    const Eigen::Vector3d far = winch_speed * u_a + r_a * u_a + (a + s_a) * w_a.cross(u_a) + r_b * u_b +
                                (b + s_b) * w_b.cross(u_b);
    const double along = u.dot(far - winch_speed * u);
    const double s = stretch.axial ? chord.norm() - total : 0.0;
    const Eigen::Vector3d rate = (far - winch_speed * u - along * u) / (total + s);  // u'
    const double spin = (a * w_a.dot(u_a) + b * w_b.dot(u_b)) / total;  // the mean spin, by mass
    x.segment<3>(StateLayout::axis(next)) = u;
    x.segment<3>(StateLayout::omega(next)) = u.cross(rate) + spin * u;
    if (stretch.axial) {
      stretch.set(x, next, s, along);
      stretch.set(x, first, 0.0, 0.0);
    }
    stow(x, first);
    dynamics.deploy(next);
    outboard_length -= b;
    return WinchRegrid::kRemoved;
  }
  return WinchRegrid::kNone;
}

}  // namespace cable_dynamics
