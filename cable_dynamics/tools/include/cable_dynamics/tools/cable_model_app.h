#pragma once
/// \file
/// \brief The `cable_model` command: parse options, load the config, print the model as JSON.

#include <ostream>

namespace cable_dynamics {

/// Runs the tool; returns the process exit code (0 ok, 2 bad usage or config).
int runCableModel(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace cable_dynamics
