#include "cable_dynamics/dynamics/cable_limits.h"

#include <algorithm>
#include <cmath>

namespace cable_dynamics {
namespace {

/// Link k's length along its axis now [m]: its own (the winch's link: as paid out) plus its stretch.
double stretchedLength(const ChainModel& model, const ChainDeployment& deployed, const LinkBlocks& links, int k) {
  const double l = deployed.get(&LinkConstants::length, k);
  return model.axial() ? l + links.get(&LinkBlock::stretch, k) : l;
}

/// The largest tension along link k [N]: at its base end (tension(k)) or at its far end, the force the
/// outboard part is held with there along link k's axis (the next joint's, or the load's); compression
/// counts as 0. Under distributed loads the axial force is monotone along a link, so an end holds it.
double largestTension(const ChainData& data, const Eigen::VectorXd& tension, const Eigen::Vector3d& load_force,
                      const Eigen::Vector3d& axis, int k, int n) {
  const Eigen::Vector3d far = k + 1 < n ? Eigen::Vector3d(data.joint_force.col(k + 1)) : load_force;
  return std::max({tension(k), -far.dot(axis), 0.0});
}

}  // namespace

void reportLimits(const ChainModel& model, const ChainData& data, const Eigen::VectorXd& tension,
                  const Eigen::Vector3d& load_force, const SeabedReport* seabed, LimitReport& report) {
  const LinkProperties& p = data.deployed.properties();
  const LinkBlocks& links = data.links;
  const int n = model.links(), first = data.deployed.firstLink();
  // Every scalar back to its default; the two vectors move through the fresh report and back, so their
  // buffers are kept (no allocation once sized).
  report = LimitReport{std::move(report.bend_radius), std::move(report.utilisation)};
  report.bend_radius.resize(n);  // a no-op after the first call
  report.utilisation.resize(n);
  report.bend_radius.setConstant(LimitReport::kStraight);
  report.utilisation.setZero();
  report.min_bend_radius_link = report.max_utilisation_link = first;
  report.max_tension_utilisation_link = report.max_bend_utilisation_link = report.seabed_clearance_link = first;

  // Joint radii: joint `first` against the base's clamp, the inner joints between their links.
  for (int k = first; k < n; ++k) {
    const Eigen::Vector3d u = links.get(&LinkBlock::u, k).normalized();
    if (k > first) {
      const Eigen::Vector3d prev = links.get(&LinkBlock::u, k - 1).normalized();
      report.bend_radius(k) =
          jointBendRadius(stretchedLength(model, data.deployed, links, k - 1), stretchedLength(model, data.deployed, links, k), (prev - u).norm());
    } else if (p.clamped_base) {
      const Eigen::Vector3d clamp = data.clamp_axis.normalized();
      report.bend_radius(k) = clampBendRadius(stretchedLength(model, data.deployed, links, k), clamp.cross(u).norm(), clamp.dot(u));
    }
  }
  // The tip's clamp bends the last link at its far end.
  double tip_radius = LimitReport::kStraight;
  if (p.clamped_tip) {
    const Eigen::Vector3d u = links.get(&LinkBlock::u, n - 1).normalized(), clamp = data.tip_clamp_axis.normalized();
    tip_radius = clampBendRadius(stretchedLength(model, data.deployed, links, n - 1), clamp.cross(u).norm(), clamp.dot(u));
  }

  const bool tension_limit = p.max_tension > 0.0;
  for (int k = first; k < n; ++k) {
    const double radius = std::min(report.bend_radius(k), k + 1 < n ? report.bend_radius(k + 1) : tip_radius);
    const double mbr = p.min_bend_radius(k);
    const double by_tension =
        tension_limit ? largestTension(data, tension, load_force, links.get(&LinkBlock::u, k).normalized(), k, n) / p.max_tension
                      : 0.0;
    const double by_bend = mbr > 0.0 ? mbr / radius : 0.0;  // mbr / inf = 0: a straight link
    report.utilisation(k) = std::max(by_tension, by_bend);
    if (radius < report.min_bend_radius) {
      report.min_bend_radius = radius;
      report.min_bend_radius_link = k;
    }
    if (report.utilisation(k) > report.max_utilisation) {
      report.max_utilisation = report.utilisation(k);
      report.max_utilisation_link = k;
    }
    if (by_tension > report.max_tension_utilisation) {
      report.max_tension_utilisation = by_tension;
      report.max_tension_utilisation_link = k;
    }
    if (by_bend > report.max_bend_utilisation) {
      report.max_bend_utilisation = by_bend;
      report.max_bend_utilisation_link = k;
    }
  }
  report.tension_exceeded = report.max_tension_utilisation > 1.0;
  report.bend_exceeded = report.max_bend_utilisation > 1.0;

  // The seabed clearance: over the links the bed does not push on, the heights of their ends above the
  // bottom, leaving out an end a grounded neighbour shares (it lies at the touchdown by design).
  const Seabed& bed = model.seabedContact().bed;
  if (seabed == nullptr || !bed.enabled()) return;
  const auto grounded = [&](int k) { return k >= first && k < n && seabed->normal_force(k) > 0.0; };
  const auto end = [&](int e) -> Eigen::Vector3d {
    return e < n ? Eigen::Vector3d(links.get(&LinkBlock::base_pos, e)) : data.tip_position;
  };
  for (int k = first; k < n; ++k) {
    if (grounded(k)) continue;
    for (int e : {k, k + 1}) {
      if (grounded(e == k ? k - 1 : k + 1)) continue;
      const Eigen::Vector3d point = end(e);
      const double height = bed.probe(point.x(), point.y()).depth - point.z();  // paper z down [m]
      if (height < report.seabed_clearance) {
        report.seabed_clearance = height;
        report.seabed_clearance_link = k;
      }
    }
  }
  report.clearance_exceeded = p.min_seabed_clearance >= 0.0 && report.seabed_clearance < p.min_seabed_clearance;
}

}  // namespace cable_dynamics
