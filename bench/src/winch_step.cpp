// What the winch adds to a step (issue: at most 10 % at n = 100): the fluid_step cable (water, 1 m/s
// current, 3 Gauss points per link, added mass, 10 kg load; RK4, dt = 1 ms) with n links deployed,
// without a winch, with a winch that could pay out as much again (n more slots on the drum) standing
// still, and with it paying out at 0.2 m/s (a link added every 2.5 s at n = 100). Cases interleaved in
// each of 5 repetitions, median; ratios to the case without a winch.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "step_timing.h"


int main(int argc, char** argv) {
  const std::vector<int> sizes = bench::sizesFrom(argc, argv, {30, 100, 300});
  const char* const config = bench::fluidCableConfig();
  std::printf("\n6) the winch's cost: the fluid_step cable with n links deployed, RK4, dt = 1 ms: wall time per\n"
              "   step [ns], median of 5 interleaved; a winch with n more slots on the drum, still or paying out\n");
  std::printf("%-6s %12s %12s %12s %10s %10s\n", "n", "no winch", "winch still", "paying out", "still/no", "out/no");
  constexpr int kRepetitions = 5;
  std::vector<std::vector<std::vector<double>>> times(sizes.size(), std::vector<std::vector<double>>(3));
  for (int rep = 0; rep < kRepetitions; ++rep) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const int n = sizes[s];
      for (int c = 0; c < 3; ++c) {
        std::vector<std::string> overrides = {"cable.links=" + std::to_string(n)};
        if (c > 0) {
          overrides.push_back("winch.max_length=100.0");
          overrides.push_back(std::string("winch.speed=") + (c == 2 ? "0.2" : "0.0"));
        }
        cable_dynamics::CableSimulator sim(cable_dynamics::loadConfigString(config, overrides));
        for (int i = 0; i < 20; ++i) sim.step();
        times[s][c].push_back(bench::stepNanoseconds(sim, 0.3));
      }
    }
  }
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const double none = bench::median(times[s][0]), still = bench::median(times[s][1]), paying = bench::median(times[s][2]);
    std::printf("%-6d %12.0f %12.0f %12.0f %10.3f %10.3f\n", sizes[s], none, still, paying, still / none, paying / none);
  }
  return 0;
}
