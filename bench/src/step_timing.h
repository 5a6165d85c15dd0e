#pragma once
/// \file
/// \brief What the project-only benchmarks (fluid_step, winch_step) share: the sizes from the command
///        line, the wall time of a simulator's step, the fluid cable's config, a median.

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace bench {

/// The cable of the fluid tables: 50 m, 25 mm, 0.6 kg/m, a 10 kg load, water with a 1 m/s current,
/// tilted 0.3 rad; the number of links is set with --set-style overrides (cable.links=N).
inline const char* fluidCableConfig() {
  return "cable: {links: 1, length: 50.0, diameter: 0.025, mass_per_length: 0.6}\n"
         "load: {mass: 10.0, volume: 0.005, drag_area: 0.2}\n"
         "fluid: {density: 1025.0, drag_normal: 1.2, drag_tangential: 0.01, added_mass: 1.0, current: [1.0, 0.0, 0.0]}\n"
         "initial: {elevation: 0.3}\n";
}

/// Sizes from argv[1] ("10,100,1000"), or `fallback` without an argument.
inline std::vector<int> sizesFrom(int argc, char** argv, std::vector<int> fallback) {
  if (argc <= 1) return fallback;
  std::vector<int> sizes;
  for (std::string list = argv[1]; !list.empty();) {
    const size_t comma = list.find(',');
    sizes.push_back(std::stoi(list.substr(0, comma)));
    list = comma == std::string::npos ? "" : list.substr(comma + 1);
  }
  return sizes;
}

/// Wall time per step [ns], stepping in tens for at least `target_seconds` of wall time.
inline double stepNanoseconds(cable_dynamics::CableSimulator& sim, double target_seconds) {
  long steps = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < target_seconds) {
    for (int i = 0; i < 10; ++i) sim.step();
    steps += 10;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return 1e9 * elapsed / steps;
}

/// The median of `v`, -1 when empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace bench
