// Issue 15's benchmark: the stiff presets (config/rov_tether.yaml, config/armoured_umbilical.yaml) at
// n = 25, 100, 300, 1000, wall time per simulated second, all in one run:
// - RK4 at its recommended stable step (estimateStableStep: half its limit),
// - the implicit integrator at its recommended step, the preset as configured (water, current, ROV),
// - the dense semi-implicit integrator at 10 ms (n <= 300: at 1000 its 3000 x 3000 LU is tens of seconds a step),
// - the implicit integrator and DART 6 with joint springs and dampers on the same chain at the same step,
//   in air with a free load (DART has no fluid and no coupling): the like-for-like pair.
// Every system starts from the preset's static equilibrium, the same state (the DART pair: see below). Usage: stiff_step [sizes] [seconds]
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "chain_spec.h"
#include "dart_springs.h"
#include "step_timing.h"

namespace {

using cable_dynamics::CableParams;
using cable_dynamics::CableSimulator;

/// Wall seconds per simulated second of `step` at `dt`, stepping for at least `budget` seconds of wall
/// time (and 3 steps). `ok` turns false on a failed or retried step.
template <typename Step>
double secondsPerSimulatedSecond(Step step, double dt, double budget) {
  long steps = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < budget || steps < 3) {
    step();
    ++steps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return elapsed / (steps * dt);
}

/// A simulator of `params` from its configured start (the presets: the static equilibrium, solved again
/// for each system: the ROV's target is set relative to that start, so a state copied in through the
/// paper angles would put the target tens of metres from the tip).
struct Started {
  CableSimulator sim;
  bool ok = true;
  long retried = 0;
  explicit Started(const CableParams& params) : sim(params) {}
  double time(double budget) {
    return secondsPerSimulatedSecond(
        [this] {
          const cable_dynamics::StepReport r = sim.step();
          ok = ok && r.ok;
          if (r.substeps > 1) ++retried;
        },
        sim.dt(), budget);
  }
  std::string flag() const { return !ok ? " FAILED" : retried > 0 ? " (" + std::to_string(retried) + " retried)" : ""; }
};

void printCell(double seconds, const std::string& flag) {
  std::printf(" %10.4g s %-10s", seconds, flag.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<int> sizes = bench::sizesFrom(argc, argv, {25, 100, 300, 1000});
  const double budget = argc > 2 ? std::stod(argv[2]) : 1.0;
  std::printf("\nstiff_step: wall seconds per simulated second (real-time factor = 1 / it); each cell steps for at least %.2g s\n",
              budget);
  for (const std::string preset : {"rov_tether", "armoured_umbilical"}) {
    std::printf("\n%s (config/%s.yaml)\n", preset.c_str(), preset.c_str());
    std::printf("%6s %-26s %-26s %-26s %-26s %-26s\n", "n", "rk4 (its stable dt)", "implicit (preset, 10 ms)",
                "semi_implicit (10 ms)", "implicit, air (10 ms)", "DART springs, air (10 ms)");
    double implicit_100 = 0.0, implicit_1000 = 0.0;
    for (const int n : sizes) {
      const CableParams params =
          cable_dynamics::loadConfigFile(std::string(BENCH_CONFIG_DIR) + "/" + preset + ".yaml", {"cable.links=" + std::to_string(n)});
      CableSimulator start(params);  // for its link properties
      const cable_dynamics::StableStep stable = cable_dynamics::estimateStableStep(params, start.properties());
      std::printf("%6d", n);
      std::fflush(stdout);
      // RK4 at its recommended step, halved until 0.2 s of simulated time need no retried step (the
      // estimate is not always on the safe side: the table says when it was not).
      CableParams rk4 = params;
      rk4.simulation.integrator = cable_dynamics::Integrator::kRk4;
      rk4.simulation.dt = stable.recommended;
      for (int halvings = 0; halvings < 6; ++halvings) {
        Started trial(rk4);
        bool clean = true;
        for (long i = 0; i * rk4.simulation.dt < 0.2 && clean; ++i) {
          const cable_dynamics::StepReport r = trial.sim.step();
          clean = r.ok && r.substeps == 1;
        }
        if (clean) break;
        rk4.simulation.dt *= 0.5;
      }
      {
        Started s(rk4);
        const double t = s.time(budget);
        char cell[64];
        std::snprintf(cell, sizeof cell, "(dt %.2g%s)%s", rk4.simulation.dt, rk4.simulation.dt < stable.recommended ? "*" : "",
                      s.flag().c_str());
        std::printf(" %10.4g s %-14s", t, cell);
      }
      // The implicit integrator on the preset.
      CableParams implicit = params;
      implicit.simulation.dt = stable.implicit_recommended;
      {
        Started s(implicit);
        const double t = s.time(budget);
        printCell(t, s.flag());
        if (n == 100) implicit_100 = t;
        if (n == 1000) implicit_1000 = t;
      }
      // The dense semi-implicit reference.
      if (n <= 300) {
        CableParams semi = params;
        semi.simulation.integrator = cable_dynamics::Integrator::kSemiImplicit;
        semi.simulation.dt = 0.01;
        Started s(semi);
        printCell(s.time(budget), s.flag());
      } else {
        std::printf(" %-25s", "(not run: O(n^3))");
      }
      // Like for like with DART: in air, free load, the preset's springs and dampers, 10 ms, both from
      // the cable hanging straight and tilted 0.05 rad at its clamp (released from its shape in water
      // into air, DART's step diverged at n = 100 and aborted on its own assertion).
      CableParams air = params;
      air.fluid.density = 0.0;
      air.load.mode = cable_dynamics::LoadMode::kFree;
      air.simulation.dt = 0.01;
      air.initial.mode = cable_dynamics::InitialMode::kAngles;
      for (double& e : air.initial.elevation) e = 0.05;
      for (double& a : air.initial.azimuth) a = 0.0;
      Started project(air);
      std::vector<Eigen::Vector3d> axes;  // DART's start: the same shape at rest
      for (int k = 0; k < n; ++k) axes.push_back(project.sim.state().segment<3>(cable_dynamics::StateLayout::axis(k)));
      const double project_time = project.time(budget);
      printCell(project_time, project.flag());
#ifdef BENCH_HAVE_DART
      {
        const bench::ChainSpec spec = bench::makeSpec(air, axes);
        const cable_dynamics::LinkProperties& p = start.properties();
        bench::JointSprings springs;
        for (int k = 0; k < n; ++k) {
          springs.bending.push_back(p.stiffness_elevation(k));
          springs.torsion.push_back(p.stiffness_torsion(k));
          springs.bending_damping.push_back(p.damping_elevation(k));
          springs.torsion_damping.push_back(p.damping_torsion(k));
        }
        const auto dart = bench::makeDartSprings(spec, springs);
        const double t = secondsPerSimulatedSecond([&] { dart->step(); }, spec.dt, budget);
        printCell(t, dart->finite() ? "" : " NON-FINITE");
        std::printf("  implicit / DART = %.3g", project_time / t);
      }
#else
      std::printf(" %-25s", "(DART not found)");
#endif
      std::printf("\n");
      std::fflush(stdout);
    }
    if (implicit_100 > 0.0 && implicit_1000 > 0.0) {
      std::printf("implicit, preset: time(n = 1000) / time(n = 100) = %.3g; real-time factor %.3g at n = 100, %.3g at n = 1000\n",
                  implicit_1000 / implicit_100, 1.0 / implicit_100, 1.0 / implicit_1000);
    }
  }
  return 0;
}
