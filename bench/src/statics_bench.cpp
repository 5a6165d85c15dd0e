// Wall time of solveStatics (statics/static_solver.h) on the default umbilical (config/default.yaml:
// 50 m, 10 kg load, 0.3 m/s current) at n = 100 and n = 1000, free tip and anchored tip (30 m across,
// 35 m down, the default 2e4 N/m coupling), and the same cable made stiff (bending model, EI = 200 N m^2),
// which is where Newton does the work (the limp starts are already the answer). Median of 7 solves.
// Usage: statics_bench [config.yaml] (default: the repository's config/default.yaml).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/statics/static_solver.h"

using namespace cable_dynamics;

int main(int argc, char** argv) {
  const std::string config = argc > 1 ? argv[1] : std::string(BENCH_CONFIG_DIR) + "/default.yaml";
  std::printf("solveStatics on %s, median of 7 [ms]\n", config.c_str());
  std::printf("%-6s %-8s %-8s %10s %6s %10s %s\n", "n", "cable", "tip", "time", "iters", "residual", "message");
  for (int n : {100, 1000}) {
    for (bool stiff : {false, true}) {
      for (bool coupled : {false, true}) {
        std::vector<std::string> o = {"cable.links=" + std::to_string(n)};
        if (coupled) o.push_back("load.mode=anchored");
        if (stiff) o.push_back("cable.stiffness={model: bending, bending_rigidity: 200, torsional_rigidity: 100}");
        const CableParams params = loadConfigFile(config, o);
        const ChainModel model(params);
        const ChainDeployment deployed = model.initialDeployment();
        const CurrentField current(params.fluid);
        StaticProblem problem;
        problem.tip_coupled = coupled;
        problem.target_position = Eigen::Vector3d(30.0, 0.0, 35.0);
        std::vector<double> times;
        StaticSolution s;
        for (int rep = 0; rep < 7; ++rep) {
          const auto start = std::chrono::steady_clock::now();
          s = solveStatics(model, deployed, current, problem);
          times.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::nth_element(times.begin(), times.begin() + 3, times.end());
        std::printf("%-6d %-8s %-8s %10.3f %6d %10.2e %s\n", n, stiff ? "stiff" : "limp", coupled ? "anchored" : "free",
                    times[3], s.iterations, s.residual, s.converged ? "" : s.message.c_str());
      }
    }
  }
  return 0;
}
