#pragma once
/// \file
/// \brief The seabed's shape in the paper frame (z down, origin at the base's rest position): a flat
///        bottom or bathymetry on a grid, bilinear in between (docs/MODEL.md section 10).

#include <Eigen/Core>

#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The seabed under one point: its depth and the unit normal pointing into the bed.
struct SeabedProbe {
  double depth = 0.0;       ///< D(x, y), paper z of the bottom [m]
  Vec3 into{0.0, 0.0, 1.0}; ///< unit normal into the bed, paper frame: (-D_x, -D_y, 1) / |.| [-]
};

class Seabed {
 public:
  Seabed() = default;  ///< none: nothing touches it
  explicit Seabed(const SeabedParams& params);

  bool enabled() const { return enabled_; }
  bool flat() const { return !grid_; }
  /// The smallest depth anywhere [m]: nothing above it touches the bed.
  double shallowest() const { return shallowest_; }

  /// The seabed at paper-frame (x, y) [m]. Within the grid: the bilinear patch and its gradient;
  /// beyond an edge, the edge's depth carries on (zero slope across it).
  SeabedProbe probe(double x, double y) const {
    SeabedProbe p;
    p.depth = flat_depth_;
    if (grid_) probeGrid(x, y, p);
    return p;
  }

  /// Penetration of the paper-frame point (x, y, z) measured along the normal, (z - D) n_z [m]; > 0 in
  /// the bed. For a plane this is the distance to it; the spring's potential 1/2 k delta^2 then has
  /// the force -k delta n, exactly (on a curved grid, to the second order in the patch's curvature).
  static double penetration(const SeabedProbe& p, double z) { return (z - p.depth) * p.into.z; }

 private:
  void probeGrid(double x, double y, SeabedProbe& p) const;

  bool enabled_ = false;
  bool grid_ = false;
  double flat_depth_ = 0.0;  ///< [m]
  double shallowest_ = 0.0;  ///< [m]
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero(), spacing_ = Eigen::Vector2d::Ones();  ///< world x, y [m]
  Eigen::MatrixXd depth_;    ///< (rows y, cols x) [m]
};

}  // namespace cable_dynamics
