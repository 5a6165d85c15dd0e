#pragma once
// For the tests of config validation: the key a config is refused for, or "(accepted)".
#include <string>

#include "cable_dynamics/params/config_loader.h"

inline std::string refusedKey(const std::string& yaml) {
  try {
    cable_dynamics::loadConfigString(yaml);
  } catch (const cable_dynamics::ConfigError& e) {
    return e.key();
  }
  return "(accepted)";
}
