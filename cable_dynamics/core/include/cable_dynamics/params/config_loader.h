#pragma once
/// \file
/// \brief Reads CableParams from a YAML config (the keys of docs/CONFIG.md), validating
///        every value.

#include <stdexcept>
#include <string>
#include <vector>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/params/config_section.h"

namespace cable_dynamics {

/// Parses and validates a config tree. Throws ConfigError on a bad, missing or unknown key. A relative
/// file name in it (seabed.grid_file) is read from `base_dir` (the working directory when empty).
CableParams parseConfig(const YAML::Node& root, const std::string& base_dir = "");

/// Applies `key.path=value` (value in YAML syntax, e.g. `cable.links=10` or `fluid.current=[1,0,0]`)
/// to the tree before it is parsed. Throws ConfigError when the override is malformed.
void applyOverride(YAML::Node& root, const std::string& assignment);

/// Loads `path`, applies the overrides in order and parses the result. Throws ConfigError.
CableParams loadConfigFile(const std::string& path, const std::vector<std::string>& overrides = {});

/// Parses a YAML string (tests and tools). Throws ConfigError.
CableParams loadConfigString(const std::string& yaml_text, const std::vector<std::string>& overrides = {});

}  // namespace cable_dynamics
