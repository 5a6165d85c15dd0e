#include "cable_dynamics/tools/cli_options.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace cable_dynamics {

std::vector<double> parseNumberList(const std::string& text, const std::string& flag) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const char* begin = item.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    const bool blank_tail = std::all_of(static_cast<const char*>(end), begin + item.size(), [](char c) { return c == ' '; });
    if (item.empty() || end == begin || !blank_tail || errno == ERANGE || !std::isfinite(v)) {
      throw UsageError(flag + ": entry " + std::to_string(values.size() + 1) + " is '" + item +
                       "': expected a comma-separated list of finite numbers");
    }
    values.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

CliOptions parseCli(int argc, const char* const* argv, const std::vector<std::string>& allowed) {
  CliOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      continue;
    }
    if (std::find(allowed.begin(), allowed.end(), flag) == allowed.end()) {
      throw UsageError("unknown option '" + flag + "'");
    }
    if (flag == "--statics") {  // the one flag without a value
      o.statics = true;
      continue;
    }
    if (i + 1 >= argc) throw UsageError(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--config") {
      o.config = value;
    } else if (flag == "--set") {
      o.overrides.push_back(value);
    } else if (flag == "--q") {
      o.q = parseNumberList(value, flag);
    } else if (flag == "--qd") {
      o.qd = parseNumberList(value, flag);
    } else if (flag == "--random-state") {
      char* end = nullptr;
      const unsigned long seed = std::strtoul(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || value[0] == '-') {
        throw UsageError("--random-state is '" + value + "': expected a non-negative integer seed");
      }
      o.random_seed = static_cast<unsigned>(seed);
    } else if (flag == "--duration") {
      const std::vector<double> d = parseNumberList(value, flag);
      if (d.size() != 1 || d[0] <= 0.0) throw UsageError("--duration is '" + value + "': expected one number > 0 [s]");
      o.duration = d[0];
    } else if (flag == "--sample") {
      const std::vector<double> d = parseNumberList(value, flag);
      if (d.size() != 1 || d[0] <= 0.0) throw UsageError("--sample is '" + value + "': expected one number > 0 [s]");
      o.sample = d[0];
    } else if (flag == "--output") {
      o.output = value;
    } else if (flag == "--plot") {
      o.plot = value;
    } else if (flag == "--bag") {
      o.bag = value;
    }
  }
  return o;
}

}  // namespace cable_dynamics
