#pragma once
/// \file
/// \brief Checks a `reset` service request with the config loader's ranges for the `initial` keys.

#include <string>
#include <vector>

#include "cable_dynamics/urdf/cable_urdf.h"

namespace cable_dynamics {

/// Largest |joint rate| a reset may set [rad/s].
constexpr double kMaxResetRate = 1e3;

/// true when `positions` (3n, or empty: back to the configured state) and `velocities` (3n or empty; only
/// with positions) are acceptable: elevation and azimuth in [-pi, pi], torsion in [-1000, 1000] [rad] (as
/// initial.elevation/azimuth/torsion), every rate finite with |qd| <= kMaxResetRate. Otherwise false, and
/// `why` names the entry, its joint, the value and the allowed range. With a winch, `stored_links` is the
/// number of slots on the drum at the configured deployment: their entries (the first 3 stored_links of
/// each array) must be 0 (on the drum a slot hangs straight down, at rest; a drum slot's relative azimuth
/// would turn the deployed cable).
bool checkResetRequest(const std::vector<double>& positions, const std::vector<double>& velocities, int links,
                       const CableFrameNames& names, std::string& why, int stored_links = 0);

}  // namespace cable_dynamics
