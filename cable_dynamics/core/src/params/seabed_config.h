#pragma once
// The `seabed:` section of a config (config_loader.cpp calls it after the cable, its sections and the
// fluid, whose diameters set the default penetration). Internal to the config loader.

#include <string>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/params/config_section.h"

namespace cable_dynamics {

/// Reads `seabed` into p.seabed. A relative `grid_file` is read from `base_dir` (the config file's
/// folder; the working directory when empty). Throws ConfigError naming the key.
void parseSeabed(ConfigSection seabed, const std::string& base_dir, CableParams& p);

}  // namespace cable_dynamics
