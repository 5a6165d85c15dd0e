#include "cable_dynamics/ros/winch_request.h"

#include <cmath>
#include <sstream>

namespace cable_dynamics {

const char* const kNoWinchMessage = "no winch is configured (config key winch:): the cable's length is fixed";

bool checkWinchLength(double length, const WinchParams& winch, std::string& why) {
  if (!winch.enabled) {
    why = kNoWinchMessage;
    return false;
  }
  if (std::isfinite(length) && length >= winch.min_length && length <= winch.max_length) return true;
  std::ostringstream s;
  s << "length " << length << " m refused: expected a finite length in [" << winch.min_length << ", "
    << winch.max_length << "] m (winch.min_length, winch.max_length)";
  why = s.str();
  return false;
}

}  // namespace cable_dynamics
