#include "cable_dynamics/ros/winch_request.h"

#include <stdexcept>

namespace cable_dynamics {

bool checkWinchLength(double length, const WinchParams& winch, std::string& why) {
  if (!winch.enabled) {
    why = kNoWinchMessage;
    return false;
  }
  try {
    checkWinchLength(length, winch);  // the simulator's gate: its range and message
  } catch (const std::invalid_argument& e) {
    why = e.what();
    return false;
  }
  return true;
}

}  // namespace cable_dynamics
