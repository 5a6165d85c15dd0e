#pragma once
/// \file
/// \brief What the node accepts as a tf2 frame name: checked on `ros.world_frame`, `ros.frame_prefix` and
///        every input's header.frame_id before tf2 sees it (tf2 prints a warning per call for a bad name).

#include <string>

namespace cable_dynamics {

/// true for a name tf2 accepts without complaint: not empty, no leading '/', no whitespace or control
/// character.
bool isValidFrameName(const std::string& name);

/// true for "" (no prefix) or a string that is a valid frame name.
bool isValidFramePrefix(const std::string& prefix);

}  // namespace cable_dynamics
