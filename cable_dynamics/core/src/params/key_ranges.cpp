#include "cable_dynamics/params/key_ranges.h"

#include <sstream>

namespace cable_dynamics {

std::string NumberRange::text() const {
  std::ostringstream s;
  s << "a finite number";
  if (std::isfinite(lo) && std::isfinite(hi)) {
    s << " in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
  } else if (std::isfinite(lo)) {
    s << (lo_open ? " > " : " >= ") << lo;
  } else if (std::isfinite(hi)) {
    s << " <= " << hi;
  }
  if (unit != nullptr && *unit != '\0') s << " [" << unit << "]";
  return s.str();
}

std::string IntegerRange::text() const {
  return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

}  // namespace cable_dynamics
