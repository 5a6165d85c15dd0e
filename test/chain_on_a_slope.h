#pragma once
/// \file
/// \brief The slope case of test_seabed and test_static_friction, written once: a 20 m chain (20 links,
///        2 kg/m, in air) pinned at its base, lying across a plane that deepens along world x at
///        tan(theta), so that the slope pulls every link down along x, normal to the chain (the lateral
///        friction coefficient decides). The plane is a 2 x 2 grid (bilinear: exact), 0.01 m below the
///        chain's rest height at the base.

#include <cmath>
#include <string>
#include <vector>

#include "cable_dynamics/params/config_loader.h"

namespace cable_dynamics {

/// The chain on a plane `degrees` steep, friction coefficients `mu` (axial and lateral) and the friction's
/// keys `friction_extra` (", breakout: 0.0" or empty), with `overrides` on top (RK4 at 0.5 ms unless they
/// say otherwise).
inline CableParams chainOnASlope(double degrees, double mu, const std::string& friction_extra,
                                 const std::vector<std::string>& overrides = {}) {
  const double slope = std::tan(degrees * M_PI / 180.0);
  const std::string low = std::to_string(0.01 - 100.0 * slope), high = std::to_string(0.01 + 100.0 * slope);
  const std::string grid =
      "{origin: [-100.0, -100.0], spacing: [200.0, 200.0], depth: [[" + low + ", " + high + "], [" + low + ", " + high + "]]}";
  const std::string friction = "{axial: " + std::to_string(mu) + ", lateral: " + std::to_string(mu) +
                               ", velocity: 0.01" + friction_extra + "}";
  return loadConfigString(
      "cable: {links: 20, length: 20.0, diameter: 0.04, mass_per_length: 2.0}\n"
      "fluid: {density: 0.0}\n"
      "seabed: {grid: " + grid + ", friction: " + friction + "}\n"
      "initial: {elevation: 1.5707963267948966, azimuth: 0.0}\n"
      "simulation: {dt: 0.0005}\n",
      overrides);
}

}  // namespace cable_dynamics
