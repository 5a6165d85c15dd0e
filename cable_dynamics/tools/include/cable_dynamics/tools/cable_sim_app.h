#pragma once
/// \file
/// \brief The `cable_sim` command: run the simulation offline (no roscore), write a CSV and a plot.

#include <ostream>

namespace cable_dynamics {

/// Runs the tool; returns the exit code (0 ok, 2 bad usage or config, 3 the simulation diverged,
/// 4 the output could not be written).
int runCableSim(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace cable_dynamics
