// What the seabed adds to a step (issue 13: at most 25 % at n = 100 with half the cable on the bottom):
// the fluid_step cable (50 m, water, a current of 0.1 m/s (at 1 m/s the drag lifts this light cable off the bottom), 3 Gauss points per link, added mass, 10 kg load;
// RK4, dt = 1 ms) anchored 40 m out on a bottom 20 m below its base, each started from its equilibrium:
// with no seabed (hanging through it), with the seabed and no friction, with friction (0.3 along, 0.6
// across; static friction, the default: an anchor per contact point), and with the regularized friction
// alone (seabed.friction.breakout 0, no anchors). Cases interleaved in each of 5 repetitions, median;
// ratios to the case without a seabed. The grounded length is printed beside them.
#include <cstdio>
#include <string>
#include <vector>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "step_timing.h"

int main(int argc, char** argv) {
  const std::vector<int> sizes = bench::sizesFrom(argc, argv, {30, 100, 300});
  const char* const config = bench::fluidCableConfig();
  std::printf("\n7) the seabed's cost: the fluid_step cable in 0.1 m/s, anchored 40 m out on a bottom 20 m down, RK4, dt = 1 ms:\n"
              "   wall time per step [ns], median of 5 interleaved; the seabed without friction, with static friction\n"
              "   (anchors, the default) and with the regularized friction alone (breakout 0)\n");
  std::printf("%-6s %10s %12s %12s %12s %12s %10s %10s %10s\n", "n", "grounded", "no seabed", "seabed", "+static", "+regular.",
              "bed/no", "static/no", "regul./no");
  constexpr int kRepetitions = 5;
  constexpr int kCases = 4;
  std::vector<std::vector<std::vector<double>>> times(sizes.size(), std::vector<std::vector<double>>(kCases));
  std::vector<double> grounded(sizes.size(), 0.0);
  for (int rep = 0; rep < kRepetitions; ++rep) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const int n = sizes[s];
      const std::vector<std::string> common = {"cable.links=" + std::to_string(n), "load.mode=anchored",
                                               "load.motion.offset=[40.0, 0.0, 30.0]", "initial.elevation=0.0",
                                               "initial.mode=equilibrium", "fluid.current=[0.1, 0.0, 0.0]", "seabed.depth=20.0"};
      for (int c = 0; c < kCases; ++c) {
        // Each from its own equilibrium: without a seabed the cable hangs through the bottom; a step's
        // work is the same but for the contact.
        std::vector<std::string> overrides = common;
        if (c == 0) overrides.pop_back();  // no seabed
        if (c == 2) overrides.push_back("seabed.friction={axial: 0.3, lateral: 0.6}");
        if (c == 3) overrides.push_back("seabed.friction={axial: 0.3, lateral: 0.6, breakout: 0.0}");
        cable_dynamics::CableSimulator sim(cable_dynamics::loadConfigString(config, overrides));
        if (c == 1) {
          cable_dynamics::SimulationSnapshot snapshot;
          sim.snapshot(snapshot);
          grounded[s] = snapshot.chain.seabed.grounded_length;
        }
        for (int i = 0; i < 20; ++i) sim.step();
        times[s][c].push_back(bench::stepNanoseconds(sim, 0.3));
        if (sim.retriedSteps() > 0) std::printf("   (n = %d, case %d: %ld steps needed substeps)\n", n, c, sim.retriedSteps());
      }
    }
  }
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const double none = bench::median(times[s][0]), bed = bench::median(times[s][1]), friction = bench::median(times[s][2]);
    const double regularized = bench::median(times[s][3]);
    std::printf("%-6d %9.1fm %12.0f %12.0f %12.0f %12.0f %10.3f %10.3f %10.3f\n", sizes[s], grounded[s], none, bed, friction,
                regularized, bed / none, friction / none, regularized / none);
  }
  return 0;
}
