#pragma once
/// \file
/// \brief Log lines for the input guard's verdicts, throttled: one call site per reason, so a flood of one
///        kind of bad input gives one line per 5 s, never one per message.

#include "cable_dynamics/ros/input_guard.h"
#include "cable_dynamics/ros/input_verdict.h"
#include "cable_dynamics/ros/node_options.h"

namespace cable_dynamics {

/// Logs a refused or re-acquired input on `topic` (nothing for an accepted one), with the counters so far.
void logInput(const char* topic, InputVerdict verdict, const InputCounters& counters, const NodeOptions& options);
/// Logs a refused winch/speed command (nothing for an accepted one); `max_speed` [m/s] is winch.max_speed.
void logWinchSpeed(InputVerdict verdict, const InputCounters& counters, double max_speed);

}  // namespace cable_dynamics
