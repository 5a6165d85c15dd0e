#include "cable_dynamics/ros/frame_name.h"

namespace cable_dynamics {

bool isValidFrameName(const std::string& name) {
  if (name.empty() || name.front() == '/') return false;
  for (const char c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u <= ' ' || u == 0x7f) return false;  // space, tab, newline and the other control characters
  }
  return true;
}

bool isValidFramePrefix(const std::string& prefix) { return prefix.empty() || isValidFrameName(prefix); }

}  // namespace cable_dynamics
