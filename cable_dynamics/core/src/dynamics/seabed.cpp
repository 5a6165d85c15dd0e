#include "cable_dynamics/dynamics/seabed.h"

#include <algorithm>
#include <cmath>

namespace cable_dynamics {

Seabed::Seabed(const SeabedParams& params)
    : enabled_(params.enabled), grid_(params.enabled && params.has_grid), flat_depth_(params.depth) {
  shallowest_ = flat_depth_;
  if (grid_) {
    origin_ = params.grid.origin;
    spacing_ = params.grid.spacing;
    depth_ = params.grid.depth;
    shallowest_ = depth_.minCoeff();
  }
}

void Seabed::probeGrid(double x, double y, SeabedProbe& p) const {
  // The grid is in world axes: world (x, y) = paper (x, -y).
  const int nx = static_cast<int>(depth_.cols()), ny = static_cast<int>(depth_.rows());
  const double gx = (x - origin_.x()) / spacing_.x(), gy = (-y - origin_.y()) / spacing_.y();
  const int i = std::clamp(static_cast<int>(std::floor(gx)), 0, nx - 2);
  const int j = std::clamp(static_cast<int>(std::floor(gy)), 0, ny - 2);
  const double fx_raw = gx - i, fy_raw = gy - j;
  const double fx = std::clamp(fx_raw, 0.0, 1.0), fy = std::clamp(fy_raw, 0.0, 1.0);
  const double d00 = depth_(j, i), d10 = depth_(j, i + 1), d01 = depth_(j + 1, i), d11 = depth_(j + 1, i + 1);
  p.depth = (1.0 - fy) * ((1.0 - fx) * d00 + fx * d10) + fy * ((1.0 - fx) * d01 + fx * d11);
  // Slope along world x and y [-]; zero across an edge that the point lies beyond.
  const bool inside_x = fx_raw == fx, inside_y = fy_raw == fy;
  const double slope_x = inside_x ? ((1.0 - fy) * (d10 - d00) + fy * (d11 - d01)) / spacing_.x() : 0.0;
  const double slope_y = inside_y ? ((1.0 - fx) * (d01 - d00) + fx * (d11 - d10)) / spacing_.y() : 0.0;
  // Paper frame: D_y(paper) = -D_y(world); the normal into the bed is (-D_x, -D_y, 1) normalized.
  const double nx_paper = -slope_x, ny_paper = slope_y;
  const double inverse = 1.0 / std::sqrt(1.0 + nx_paper * nx_paper + ny_paper * ny_paper);
  p.into = {nx_paper * inverse, ny_paper * inverse, inverse};
}

}  // namespace cable_dynamics
