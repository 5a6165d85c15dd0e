// The step check judges without changing anything, and its tolerance does not loosen as a run goes
// wrong; a run whose steps keep failing the check shows it in the simulator's counters (issue 11, item 8).
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/state_layout.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/step_check.h"

using namespace cable_dynamics;

TEST(StepCheck, ToleranceDoesNotGrowWithTheAccumulatedDissipation) {
  // 0.5 J created in one step against 100 J of mechanical energy is 5e-3 of the scale: refused, however
  // much energy the run has dissipated so far. (The landed check added |dissipated| and |work| to the
  // scale: after 1e6 J dissipated it allowed 100 J a step.)
  const StepLimits limits;  // tolerance 1e-4
  EnergyBalance before, after;
  before.mechanical = after.mechanical = 100.0;
  before.dissipated = after.dissipated = -1e6;
  before.value = 10.0;
  after.value = 10.5;
  EXPECT_EQ(judgeEnergy(before, after, limits.energy_tolerance), StepVerdict::kEnergyCreated);
  // What the step itself dissipates does count (its own flow's round-off): 0.5 J against 100 J of
  // mechanical energy and a 1e4 J flow in this step is 5e-5 of the scale, accepted.
  after.dissipated = before.dissipated + 1e4;
  EXPECT_EQ(judgeEnergy(before, after, limits.energy_tolerance), StepVerdict::kAccepted);
  // Energy taken out is never refused.
  after.value = before.value - 50.0;
  EXPECT_EQ(judgeEnergy(before, after, limits.energy_tolerance), StepVerdict::kAccepted);
}

TEST(StepCheck, JudgingChangesNothing) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(StateLayout::size(2));
  x.segment<3>(StateLayout::axis(0)) << 0.0, 0.0, 2.0;  // not unit: judging must not renormalize it
  x.segment<3>(StateLayout::axis(1)) << 0.0, 0.0, 1.0;
  const Eigen::VectorXd copy = x;
  EXPECT_EQ(judgeStep(x, 2, StepLimits{}), StepVerdict::kAccepted);
  EXPECT_EQ(x, copy);
  x(StateLayout::omega(1)) = 2e3;  // beyond the default 1000 rad/s
  EXPECT_EQ(judgeStep(x, 2, StepLimits{}), StepVerdict::kRunawaySpin);
  x(StateLayout::omega(1)) = NAN;
  EXPECT_EQ(judgeStep(x, 2, StepLimits{}), StepVerdict::kNotFinite);
  // The projection is its own, named step.
  x(StateLayout::omega(1)) = 0.0;
  ASSERT_TRUE(projectAxes(x, 2));
  EXPECT_NEAR(x.segment<3>(StateLayout::axis(0)).norm(), 1.0, 1e-15);
}

TEST(StepCheck, AnUnstableDamperShowsInTheCounters) {
  // The configuration of issue 11, item 8, stepped directly (cable_sim and the node refuse its dt at
  // start): elevation dampers of 2000 N m s/rad on 2 m links of the bending model at dt = 1 ms, while
  // the damper's mode needs about 0.25 ms (measured: no substeps at 0.2 ms, 20 % of steps at 0.3 ms).
  // Most steps need substeps, and the energy balance drifts although every accepted step passed the
  // per-step check: both counters cable_sim fails a run on (more than 1 % retried, drift above 1e-3).
  const CableParams p = loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml",
                                       {"cable.stiffness.model=bending", "cable.damping.elevation=2000"});
  CableSimulator sim(p, SimulatorUse::kUnjudgedStep);  // beyond RK4's limit on purpose: the gate refuses it
  const long steps = 2000;
  for (long i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok);
  std::cout << "dt = 1 ms: " << sim.retriedSteps() << " of " << steps << " steps needed substeps; energy drift "
            << sim.energyDrift() << " of the scale\n";
  EXPECT_GT(sim.retriedSteps(), steps / 2);
  EXPECT_GT(sim.energyDrift(), 1e-3);
  // At a step it can take, neither counter moves.
  CableParams fine = p;
  fine.simulation.dt = 1e-4;
  // (The gate refuses 0.1 ms too: the estimate's limit is 0.055 ms, on the safe side of this mode, which
  // runs clean at 0.1 ms; unjudged here to keep what this test measures.)
  CableSimulator good(fine, SimulatorUse::kUnjudgedStep);
  for (long i = 0; i < 5000; ++i) ASSERT_TRUE(good.step().ok);
  std::cout << "dt = 0.1 ms: " << good.retriedSteps() << " retried; energy drift " << good.energyDrift() << "\n";
  EXPECT_EQ(good.retriedSteps(), 0);
  EXPECT_LT(good.energyDrift(), 1e-6);
}
