#pragma once
/// \file
/// \brief Command-line options shared by the offline tools (cable_model, cable_sim).

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cable_dynamics {

/// A malformed command line; the message says what was expected.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Options of the offline tools. Flags a tool does not use are rejected by it.
struct CliOptions {
  std::string config;                    ///< --config FILE
  std::vector<std::string> overrides;    ///< --set key.path=value (repeatable)
  std::optional<std::vector<double>> q;  ///< --q v1,...,v3n [rad]
  std::optional<std::vector<double>> qd; ///< --qd v1,...,v3n [rad/s]
  std::optional<unsigned> random_seed;   ///< --random-state SEED
  std::optional<double> duration;        ///< --duration S [s]
  std::optional<double> sample;          ///< --sample S, output interval [s]
  std::string output;                    ///< --output run.csv
  std::string plot;                      ///< --plot run.png
  std::string bag;                       ///< --bag run.bag (cable_sim: the node's topics as a rosbag)
  bool help = false;                     ///< --help / -h
  bool statics = false;                  ///< --statics (cable_sim: the static equilibrium only)
};

/// Parses argv. `allowed` lists the flags the tool accepts (e.g. {"--config", "--set", "--q"}).
/// Throws UsageError on an unknown flag, a missing value or a malformed number.
CliOptions parseCli(int argc, const char* const* argv, const std::vector<std::string>& allowed);

/// Parses "v1,v2,...": every entry a finite number. `flag` names the option in the error message.
std::vector<double> parseNumberList(const std::string& text, const std::string& flag);

}  // namespace cable_dynamics
