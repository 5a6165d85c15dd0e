// The implicit step's booking of the seabed's losses, against the first law (a truth nobody here wrote):
// what the motion loses must be what the balance books as dissipated. A 20 m chain (2 kg/m, in air) pinned
// at its base lies on a flat bed (1 um below it at the start: it settles without landing); turned into the
// bed about its base at 0.02 rad/s (0.4 m/s at the tip), its contact dampers (h c / m about 5 at 10 ms)
// stop it within a step or two. Its W-method takes the
// dampers at each stage's v + dv (dv its own velocity change times gamma), not at the stage's start
// velocity: booked at the start velocity the losses came out 3.9 times the kinetic energy there was at
// 10 ms (balance +3.14 J of 1.07 J, with the bed 0.5 mm below), second order in dt (0.105 J at 2 ms,
// 0.026 J at 1 ms).
#include <cmath>
#include <iostream>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {
namespace {

struct Kick {
  double kinetic = 0.0;     ///< the kinetic energy given [J]
  double dissipated = 0.0;  ///< booked over the watch [J]
  double balance = 0.0;     ///< the balance's change over the watch (mechanical + dissipated - work) [J]
  double rise = 0.0;        ///< its largest rise at any step [J]
};

/// The chain settled on the bed for 2 s at step `dt` [s], then turned into it and watched for 1 s.
Kick kickIntoTheBed(double dt) {
  CableSimulator sim(loadConfigString(
      "cable: {links: 20, length: 20.0, diameter: 0.04, mass_per_length: 2.0}\n"
      "fluid: {density: 0.0}\n"
      "seabed: {depth: 1.0e-6, friction: {axial: 0.5, lateral: 0.5, velocity: 0.01}}\n"
      "initial: {elevation: 1.5707963267948966, azimuth: 0.0}\n"
      "simulation: {integrator: implicit, dt: " + std::to_string(dt) + "}\n"));
  for (long i = std::lround(2.0 / dt); i > 0; --i) EXPECT_TRUE(sim.step().ok);
  const long retried = sim.retriedSteps();
  SimulationSnapshot s;
  sim.snapshot(s);
  // The paper's elevations are absolute: the same rate on every joint turns the chain rigidly about its
  // base, down (decreasing elevation) into the bed.
  Eigen::VectorXd q = s.q, qd = Eigen::VectorXd::Zero(q.size());
  for (int k = 0; k < sim.links(); ++k) qd(3 * k) = -0.02;
  sim.setPaperState(q, qd);
  sim.snapshot(s);
  Kick kick;
  kick.kinetic = s.chain.kinetic_energy;
  const double start = s.total_energy, dissipated = s.dissipated_energy;
  for (long i = std::lround(1.0 / dt); i > 0; --i) {
    EXPECT_TRUE(sim.step().ok);
    sim.snapshot(s);
    kick.rise = std::max(kick.rise, s.total_energy - start);
  }
  EXPECT_EQ(sim.retriedSteps() - retried, 0);
  kick.dissipated = s.dissipated_energy - dissipated;
  kick.balance = s.total_energy - start;
  std::cout << "[ kicked into the bed, implicit at " << dt << " s ] kinetic " << kick.kinetic << " J, dissipated "
            << kick.dissipated << " J, balance moved " << kick.balance << " J (largest rise " << kick.rise << " J)\n";
  return kick;
}

TEST(ImplicitContactLosses, TheBalanceBooksWhatTheContactTakesOut) {
  const Kick at10 = kickIntoTheBed(0.01), at1 = kickIntoTheBed(0.001), at05 = kickIntoTheBed(0.0005);
  // At the recommended 10 ms: measured -0.209 J of the 1.07 J given (the booking falls short by 20 %: the
  // stage's v + dv is exact for a linear damper to 0.2 % at h c / m = 1, 4.6 % at 5 and 13 % at 10); bound
  // 0.8 J, 3.8 times, where the start velocity's booking moved +3.14 J.
  EXPECT_GT(at10.kinetic, 1.0);
  EXPECT_LT(std::abs(at10.balance), 0.8);
  // Second order in dt: measured -6.73e-4 J at 1 ms and -1.64e-4 J at 0.5 ms (order 2.04; 2.37 and 2.35
  // from 4 to 2 and 2 to 1 ms, 2.00 from 0.5 to 0.25 ms); bound 8e-4 J at 0.5 ms (4.9 times), the order
  // within [1.7, 2.5].
  EXPECT_LT(std::abs(at05.balance), 8e-4);
  const double order = std::log2(std::abs(at1.balance) / std::abs(at05.balance));  // dt halved
  std::cout << "order in dt between 1 and 0.5 ms: " << order << "\n";
  EXPECT_GT(order, 1.7);
  EXPECT_LT(order, 2.5);
  // The booking errs on the side of losses not booked: the balance never rises by more than 1e-3 of the
  // energy given (measured 0 J; the start velocity's booking rose by 3.14 J).
  for (const Kick* k : {&at10, &at1, &at05}) EXPECT_LT(k->rise, 1e-3 * k->kinetic);
}

}  // namespace
}  // namespace cable_dynamics
