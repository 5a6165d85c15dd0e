#pragma once
/// \file
/// \brief Checks a `winch/set_length` service request against the winch's configured length range.

#include <string>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/params/input_gate.h"

namespace cable_dynamics {

// kNoWinchMessage: the text a winch command gets without a winch (params/input_gate.h, the simulator's own).

/// true when `length` [m] is a target the winch can reach: a winch is configured and `length` is finite and
/// within [min_length, max_length]. Otherwise false and `why` says so, naming the range in metres.
bool checkWinchLength(double length, const WinchParams& winch, std::string& why);

}  // namespace cable_dynamics
