#pragma once
/// \file
/// \brief The `cable_sim` command: run the simulation offline (no roscore), write a CSV and a plot.

#include <ostream>

#include "cable_dynamics/tools/sample_recorder.h"

namespace cable_dynamics {

/// Runs the tool; returns the exit code (0 ok, 2 bad usage or config, 3 the simulation diverged,
/// 4 an output could not be written, 5 not reliable, 6 no static equilibrium). `bag` opens the recorder of
/// `--bag FILE` (the cable_sim executable passes the rosbag writer); without one `--bag` is refused.
int runCableSim(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                const SampleRecorderFactory& bag = {});

}  // namespace cable_dynamics
