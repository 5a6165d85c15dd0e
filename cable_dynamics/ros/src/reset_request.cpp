#include "cable_dynamics/ros/reset_request.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cable_dynamics {
namespace {

/// The ranges of the config loader's initial.elevation, .azimuth, .torsion [rad], by coordinate kind.
double positionLimit(int index) { return index % 3 == 2 ? 1e3 : M_PI; }

std::string refusal(const char* array, int i, const CableFrameNames& names, double value, double limit,
                    const char* unit) {
  std::ostringstream s;
  s << array << "[" << i << "] (" << names.joint(i) << ") = " << value << ": expected a finite number in [" << -limit
    << ", " << limit << "] [" << unit << "]";
  return s.str();
}

}  // namespace

bool checkResetRequest(const std::vector<double>& positions, const std::vector<double>& velocities, int links,
                       const CableFrameNames& names, std::string& why, int stored_links) {
  const std::size_t dof = 3 * static_cast<std::size_t>(links);
  if (positions.empty()) {
    if (velocities.empty()) return true;
    why = "velocities given without positions";
    return false;
  }
  if (positions.size() != dof || (!velocities.empty() && velocities.size() != dof)) {
    why = "state has " + std::to_string(positions.size()) + " positions and " + std::to_string(velocities.size()) +
          " velocities: expected 3n = " + std::to_string(dof) + " (velocities may be empty)";
    return false;
  }
  for (std::size_t i = 0; i < dof; ++i) {
    const double limit = positionLimit(static_cast<int>(i));
    if (!(std::abs(positions[i]) <= limit)) {
      why = refusal("positions", static_cast<int>(i), names, positions[i], limit, "rad");
      return false;
    }
  }
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    if (!(std::abs(velocities[i]) <= kMaxResetRate)) {
      why = refusal("velocities", static_cast<int>(i), names, velocities[i], kMaxResetRate, "rad/s");
      return false;
    }
  }
  const std::size_t drum = 3 * static_cast<std::size_t>(std::max(stored_links, 0));
  for (const auto* array : {&positions, &velocities}) {
    for (std::size_t i = 0; i < std::min(drum, array->size()); ++i) {
      if ((*array)[i] == 0.0) continue;
      std::ostringstream s;
      s << (array == &positions ? "positions" : "velocities") << "[" << i << "] (" << names.joint(static_cast<int>(i))
        << ") = " << (*array)[i] << ": expected 0, the slot is on the winch's drum at the configured deployment "
        << "(slots 1 to " << stored_links << ")";
      why = s.str();
      return false;
    }
  }
  return true;
}

}  // namespace cable_dynamics
