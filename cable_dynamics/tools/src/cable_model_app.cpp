#include "cable_dynamics/tools/cable_model_app.h"

#include "cable_dynamics/tools/cli_options.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/tools/model_report.h"
#include "cable_dynamics/params/states.h"

namespace cable_dynamics {
namespace {

const char* const kUsage =
    "usage: cable_model --config FILE [--set key.path=value ...]\n"
    "                   [--q v1,...,v3n --qd v1,...,v3n | --random-state SEED]\n"
    "Prints the cable's dynamic model M q'' + h + G + elastic + D q' = Q at one state as JSON.\n"
    "Without --q/--random-state the state is the config's `initial` one at rest.\n";

Eigen::VectorXd stateVector(const std::vector<double>& values, int links, const char* flag) {
  if (static_cast<int>(values.size()) != 3 * links) {
    throw UsageError(std::string(flag) + " has " + std::to_string(values.size()) + " values: expected 3n = " +
                     std::to_string(3 * links) + " (n = " + std::to_string(links) + " links)");
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

}  // namespace

int runCableModel(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  try {
    const CliOptions o = parseCli(argc, argv, {"--config", "--set", "--q", "--qd", "--random-state"});
    if (o.help) {
      out << kUsage;
      return 0;
    }
    if (o.config.empty()) throw UsageError("--config FILE is required");
    if (o.random_seed && (o.q || o.qd)) throw UsageError("give either --random-state or --q/--qd, not both");
    const CableParams params = loadConfigFile(o.config, o.overrides);
    Eigen::VectorXd q, qd;
    initialState(params, q, qd);
    if (o.random_seed) randomState(params.links, *o.random_seed, q, qd);
    if (o.q) q = stateVector(*o.q, params.links, "--q");
    if (o.qd) qd = stateVector(*o.qd, params.links, "--qd");
    out << modelReport(params, q, qd).dump(1) << "\n";
    return 0;
  } catch (const UsageError& e) {
    err << "cable_model: " << e.what() << "\n" << kUsage;
  } catch (const ConfigError& e) {
    err << "cable_model: " << e.what() << "\n";
  }
  return 2;
}

}  // namespace cable_dynamics
