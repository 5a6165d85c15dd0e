// The project's step with full fluid forces (water, 1 m/s current, Morison drag with 3 Gauss points per
// link, normal added mass, buoyancy) and a 10 kg load, for the real-time target (n = 100, RK4,
// dt = 1 ms: 50 us per step). No engine here has these forces, so this table is the project's alone:
// both formulations and all sizes in each of 5 repetitions, median.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/params/config_loader.h"
#include "step_timing.h"


int main(int argc, char** argv) {
  // Optional argument: the sizes, comma separated (default 10,30,100,300,1000).
  const std::vector<int> sizes = bench::sizesFrom(argc, argv, {10, 30, 100, 300, 1000});
  const char* const config = bench::fluidCableConfig();
  std::printf("\n5) cable_dynamics with full fluid forces (water, 1 m/s current, drag at 3 Gauss points per link,\n"
              "   added mass, 10 kg load), RK4, dt = 1 ms: wall time per step [ns], median of 5 interleaved\n");
#ifdef CABLE_DYNAMICS_NO_CLONES
  std::printf("   build: baseline x86-64 code only (CABLE_DYNAMICS_NO_CLONES)\n");
#else
  std::printf("   build: hot loops dispatched at run time (x86-64-v4 / v3 copies where the CPU has them)\n");
#endif
  std::printf("%-6s %14s %14s %10s\n", "n", "paper", "recursive", "ratio");
  // Repetitions outermost: each one measures every size and formulation back to back, so a slow minute
  // of the shared machine lands on all cells of a repetition rather than on one size.
  constexpr int kRepetitions = 5;
  std::vector<std::vector<double>> dense_times(sizes.size()), recursive_times(sizes.size());
  for (int rep = 0; rep < kRepetitions; ++rep) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const int n = sizes[s];
      for (const char* formulation : {"recursive", "paper"}) {
        if (std::string(formulation) == "paper" && n > 100) continue;  // O(n^3): seconds per step beyond
        auto params = cable_dynamics::loadConfigString(
            config, {"cable.links=" + std::to_string(n), std::string("simulation.formulation=") + formulation});
        cable_dynamics::CableSimulator sim(params);
        for (int i = 0; i < 20; ++i) sim.step();  // warm-up; also leaves the start transient
        auto& times = std::string(formulation) == "paper" ? dense_times : recursive_times;
        times[s].push_back(bench::stepNanoseconds(sim, 0.3));
      }
    }
  }
  using bench::median;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const double d = median(dense_times[s]), r = median(recursive_times[s]);
    if (d > 0) {
      std::printf("%-6d %14.0f %14.0f %10.2f\n", sizes[s], d, r, d / r);
    } else {
      std::printf("%-6d %14s %14.0f %10s\n", sizes[s], "-", r, "-");
    }
  }
  // Growth with n, from the two sizes measured back to back in each repetition.
  const auto at = [&](int n) { return std::find(sizes.begin(), sizes.end(), n) - sizes.begin(); };
  const std::size_t small = at(100), large = at(1000);
  if (small < sizes.size() && large < sizes.size()) {
    std::vector<double> ratios;
    for (int rep = 0; rep < kRepetitions; ++rep) {
      ratios.push_back(recursive_times[large][rep] / recursive_times[small][rep]);
    }
    std::sort(ratios.begin(), ratios.end());
    std::printf("recursive: time(n=1000) / time(n=100) = %.1f (median of the repetitions' ratios, %.1f to %.1f)\n",
                median(ratios), ratios.front(), ratios.back());
  }
  return 0;
}
