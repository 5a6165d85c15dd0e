// The winch at the base (docs/MODEL.md section 8): its speed and length law, and the cable it pays out
// and hauls in, against force balances and bookkeeping nobody here wrote: the line pull of a load lowered
// at constant speed (submerged weight of the deployed cable and the load, less the drag at that speed),
// the deployed length against the integral of the commanded speed, the mass against the length, and
// the energy balance with the winch's work and the paid-out cable's energy counted.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/winch.h"

using namespace cable_dynamics;

namespace {

/// A 20 m cable of 10 links under a 200 kg load, with a winch that can pay it out to `max` metres.
CableParams lowering(double density, double speed, double max, std::vector<std::string> extra = {}) {
  std::vector<std::string> o = {"fluid.density=" + std::to_string(density),
                                "winch.max_length=" + std::to_string(max),
                                "winch.speed=" + std::to_string(speed),
                                "winch.max_speed=2.0",
                                "winch.max_acceleration=0.5"};
  o.insert(o.end(), extra.begin(), extra.end());
  return loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
      "load: {mass: 200.0, volume: 0.05, drag_area: 0.5}\n"
      "simulation: {dt: 0.001}\n",
      o);
}

double deployedMass(const CableSimulator& sim) { return sim.properties().mass.sum(); }

}  // namespace

TEST(Winch, SpeedRampsAtTheAccelerationLimitAndLengthIsItsIntegral) {
  WinchParams p;
  p.enabled = true;
  p.min_length = 2.0;
  p.max_length = 100.0;
  p.max_speed = 1.0;
  p.max_acceleration = 0.5;
  Winch winch(p);
  winch.reset(10.0);
  winch.commandSpeed(0.8);
  const double h = 0.01;
  double t = 0.0;
  for (int i = 0; i < 1000; ++i, t += h) {
    winch.plan(t, h);
    winch.finish(t + h);
  }
  // 1.6 s of ramp at 0.5 m/s^2 (0.64 m), then 8.4 s at 0.8 m/s.
  EXPECT_NEAR(winch.motion().speed, 0.8, 1e-12);
  EXPECT_NEAR(winch.motion().length, 10.0 + 0.64 + 0.8 * (10.0 - 1.6), 1e-9);
  // To a target: stops there, within the acceleration limit.
  winch.commandLength(20.0);
  double top_speed = 0.0;
  for (int i = 0; i < 4000; ++i, t += h) {
    winch.plan(t, h);
    EXPECT_LE(std::abs(winch.motion().acceleration), p.max_acceleration + 1e-12);
    winch.finish(t + h);
    top_speed = std::max(top_speed, winch.motion().speed);
  }
  EXPECT_NEAR(winch.motion().length, 20.0, 1e-3);
  EXPECT_EQ(winch.motion().speed, 0.0);  // stopped, not chattering around the target
  EXPECT_LE(top_speed, p.max_speed + 1e-12);
  // Hauling in past the minimum: stops at it.
  winch.commandSpeed(-1.0);
  for (int i = 0; i < 6000; ++i, t += h) {
    winch.plan(t, h);
    winch.finish(t + h);
  }
  EXPECT_NEAR(winch.motion().length, p.min_length, 1e-3);
  EXPECT_GE(winch.motion().length, p.min_length - 1e-3);
}

// A command the winch cannot follow is refused with its range (params/input_gate.h), not clamped: the
// command in force stays. (Before the gate, commandSpeed(5) silently became 1 m/s while the node refused it.)
TEST(Winch, CommandsBeyondTheLimitsAreRefusedNotClamped) {
  WinchParams p;
  p.enabled = true;
  p.min_length = 2.0;
  p.max_length = 100.0;
  p.max_speed = 1.0;
  Winch winch(p);
  winch.reset(10.0);
  winch.commandSpeed(0.5);
  for (const double bad : {1.5, -1.0000001, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      winch.commandSpeed(bad);
      ADD_FAILURE() << "speed " << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("within +-1 m/s (winch.max_speed)"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(winch.commandedSpeed(), 0.5) << "a refused command changed the one in force";
  EXPECT_FALSE(winch.targeting());
  winch.commandSpeed(-1.0);  // the limit itself is accepted
  EXPECT_EQ(winch.commandedSpeed(), -1.0);
  for (const double bad : {1.999, 100.001, std::nan("")}) {
    try {
      winch.commandLength(bad);
      ADD_FAILURE() << "length " << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("[2, 100] m"), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(winch.targeting()) << "a refused target replaced the speed command";

  // The simulator's setters refuse the same, with the same message; without a winch, every command.
  CableSimulator sim(lowering(1025.0, 0.5, 60.0));
  EXPECT_THROW(sim.commandWinchSpeed(2.5), std::invalid_argument);
  EXPECT_EQ(sim.winch().commandedSpeed(), 0.5);
  EXPECT_THROW(sim.commandWinchLength(61.0), std::invalid_argument);
  CableSimulator fixed(loadConfigString("cable: {links: 2, length: 2.0, diameter: 0.02, mass_per_length: 0.5}\n"));
  try {
    fixed.commandWinchSpeed(0.1);
    ADD_FAILURE() << "a winch command accepted without a winch";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), kNoWinchMessage);
  }
}

TEST(Winch, TheModelAddsTheDrumsSlotsInFrontOfTheDeployedCable) {
  // The loader gives the cable as configured and counts the drum's slots; the model puts them in front
  // (issue 22: the drum's slots are built by the model, not the loader), once.
  const CableParams configured = lowering(1025.0, 0.5, 60.0);
  EXPECT_EQ(configured.links, 10);
  EXPECT_EQ(configured.link_lengths.size(), 10u);
  EXPECT_EQ(configured.initial.elevation.size(), 10u);
  EXPECT_EQ(configured.drumSlots(), 0);
  EXPECT_DOUBLE_EQ(configured.deployedLength(), 20.0);
  const CableParams p = ChainModel::withDrumSlots(configured);
  // 40 m more in 2 m links, and one more for the winch's link's band.
  EXPECT_EQ(p.winch.stored_links, 21);
  EXPECT_EQ(p.links, 31);
  EXPECT_EQ(p.drumSlots(), 21);
  EXPECT_DOUBLE_EQ(p.deployedLength(), 20.0);
  EXPECT_EQ(ChainModel::withDrumSlots(p).links, 31) << "built once";
  CableSimulator sim(configured);
  EXPECT_EQ(sim.params().links, 31);
  EXPECT_EQ(sim.firstLink(), 21);
  EXPECT_NEAR(deployedMass(sim), 0.6 * 20.0, 1e-12);
  EXPECT_THROW(loadConfigString("cable: {links: 2, length: 2.0, diameter: 0.02, mass_per_length: 0.5}\n"
                                "winch: {max_length: 1.0}\n"),
               ConfigError);
  EXPECT_THROW(loadConfigString("cable: {links: 2, length: 2.0, diameter: 0.02, mass_per_length: 0.5}\n"
                                "winch: {max_length: 10.0, schedule: [{time: 0.0, speed: 0.5, length: 3.0}]}\n"),
               ConfigError);
}

// A load lowered at a constant speed: once the speed is reached, the line pull is the submerged weight
// of what hangs below the winch less the drag at that speed (the load's, and the skin friction along
// the cable, 1/2 rho C_t pi d v^2 per metre), to rounding; in air, the weight alone.
TEST(Winch, LoweringALoadAtConstantSpeedPullsItsQuasiStaticLine) {
  for (const double density : {0.0, 1025.0}) {
    const double speed = 0.5;
    const CableParams p = lowering(density, speed, 60.0);
    CableSimulator sim(p);
    const double g = p.gravity, d = p.diameter, area = M_PI * d * d / 4.0;
    const double submerged_per_length = p.mass_per_length - density * area;
    const double load_submerged = p.load.mass - density * p.load.volume;
    SimulationSnapshot snap;
    double worst = 0.0, length_error = 0.0, mass_error = 0.0;
    const double ramp = speed / p.winch.max_acceleration;  // [s]
    for (int i = 1; i <= 60000; ++i) {
      ASSERT_TRUE(sim.step().ok);
      if (i % 500 != 0) continue;
      sim.snapshot(snap);
      const double t = sim.time();
      mass_error = std::max(mass_error, std::abs(deployedMass(sim) - p.mass_per_length * snap.deployed_length));
      if (t < ramp + 5.0) continue;
      // Length: the integral of the speed, the ramp included.
      const double expected_length = 20.0 + 0.5 * speed * ramp + speed * (t - ramp);
      length_error = std::max(length_error, std::abs(snap.deployed_length - expected_length));
      const double drag = 0.5 * density * (p.load.drag_area + p.fluid.drag_tangential * M_PI * d * snap.deployed_length) *
                          speed * speed;
      const double expected = g * (submerged_per_length * snap.deployed_length + load_submerged) - drag;
      worst = std::max(worst, std::abs(snap.line_pull - expected) / expected);
    }
    std::cout << "density " << density << ": line pull off by at most " << 100.0 * worst << " %, length by "
              << length_error << " m, mass by " << mass_error << " kg; links added " << sim.linksAdded()
              << ", deployed " << snap.deployed_length << " m" << std::endl;
    // The cable hangs straight and the speed is constant: the balance is exact up to rounding. Measured:
    // line pull 8.3e-16 relative (the simulation without skin friction is off by 0.35 % in water, which
    // the former 1 % passed), length 1.1e-10 m (the speed summed over 60000 steps), mass 3.6e-15 kg;
    // about 6x above.
    EXPECT_LT(worst, 5e-15);
    EXPECT_LT(length_error, 7e-10);  // [m]
    EXPECT_LT(mass_error, 2e-14);    // [kg]
    EXPECT_GT(sim.linksAdded(), 10);
    EXPECT_LT(sim.energyDrift(), 1e-3);
    EXPECT_EQ(sim.retriedSteps(), 0);
  }
}

namespace {

/// Runs `sim` for `seconds` [s], failing on a step that is not ok.
void run(CableSimulator& sim, double seconds) {
  const long steps = std::lround(seconds / sim.dt());
  for (long i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok) << "at t = " << sim.time();
}

/// In water, a 20 m cable of 10 links under a 50 kg load in a 0.3 m/s current, with a winch to 45 m.
CableParams inCurrent(double speed) {
  return loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
      "load: {mass: 50.0, volume: 0.02, drag_area: 0.3}\n"
      "fluid: {current: [0.3, 0.0, 0.0]}\n"
      "winch: {max_length: 45.0, max_speed: 2.0, max_acceleration: 1.0}\n"
      "simulation: {dt: 0.001}\n",
      {"winch.speed=" + std::to_string(speed)});
}

}  // namespace

// A swinging cable in air paid out and hauled in: the balance kinetic + potential - (work of the base
// force on the paid-out material + the energy that material carries out of the winch) - what merging
// links took out stays put. It fails if the dynamics miss the sliding material's Coriolis term 2 v u'.
TEST(Winch, EnergyBalanceHoldsWithTheWinchsWorkCounted) {
  CableParams p = loadConfigString(
      "cable: {links: 8, length: 8.0, diameter: 0.02, mass_per_length: 0.5}\n"
      "load: {mass: 5.0}\n"
      "fluid: {density: 0.0}\n"
      "initial: {elevation: 0.5}\n"
      "winch: {max_length: 16.0, min_length: 4.0, max_speed: 1.0, max_acceleration: 2.0, schedule: "
      "[{time: 0.0, speed: 0.6}, {time: 8.0, speed: -0.6}, {time: 20.0, speed: 0.0}]}\n"
      "simulation: {dt: 0.0005}\n");
  CableSimulator sim(p);
  SimulationSnapshot snap;
  sim.snapshot(snap);
  const double start = snap.total_energy;
  double scale = 0.0, worst = 0.0;
  for (int i = 0; i < 44000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 100 != 0) continue;
    sim.snapshot(snap);
    scale = std::max({scale, std::abs(snap.chain.kinetic_energy) + std::abs(snap.chain.potential_energy)});
    worst = std::max(worst, std::abs(snap.total_energy - start));
  }
  std::cout << "balance moved by " << worst << " J of " << scale << " J; links added " << sim.linksAdded()
            << ", removed " << sim.linksRemoved() << ", merges took " << sim.regridEnergy() << " J; drift "
            << sim.energyDrift() << std::endl;
  EXPECT_GT(sim.linksAdded(), 2);
  EXPECT_GT(sim.linksRemoved(), 4);
  EXPECT_LT(worst, 1e-4 * scale);
  EXPECT_LT(sim.energyDrift(), 1e-4);
  EXPECT_EQ(sim.retriedSteps(), 0);
}

namespace {

/// The line pull's largest relative jump from one step to the next while a cable is paid out 20 m at
/// `speed` [m/s] and hauled back in, in a current: in the steps where a link is added, where one is
/// removed, and in the other steps at a steady winch speed.
struct PullJumps {
  double added = 0.0, removed = 0.0, steady = 0.0;  // [-], relative to the line pull
  int links_added = 0, links_removed = 0;
  long retried = 0;
};

PullJumps linePullJumps(const char* stiffness, double speed) {
  const CableParams p = loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
      "load: {mass: 50.0, volume: 0.02, drag_area: 0.3}\n"
      "fluid: {current: [0.3, 0.0, 0.0]}\n"
      "winch: {max_length: 45.0, max_speed: 2.0, max_acceleration: 1.0}\n"
      "initial: {mode: equilibrium}\n"
      "simulation: {dt: 0.001}\n",
      {std::string("cable.stiffness=") + stiffness});
  CableSimulator sim(p);
  PullJumps out;
  run(sim, 5.0);
  SimulationSnapshot snap;
  sim.snapshot(snap);
  double previous = snap.line_pull;
  const double travel = 20.0;  // [m] out, then back in
  for (const double v : {speed, -speed}) {
    sim.commandWinchSpeed(v);
    const long steps = std::lround((travel / speed + 2.0) / sim.dt());
    for (long i = 0; i < steps; ++i) {
      const int first = sim.firstLink();
      EXPECT_TRUE(sim.step().ok) << "at t = " << sim.time();
      sim.snapshot(snap);
      const double jump = std::abs(snap.line_pull - previous) / snap.line_pull;
      if (sim.firstLink() < first) {
        out.added = std::max(out.added, jump);
      } else if (sim.firstLink() > first) {
        out.removed = std::max(out.removed, jump);
      } else if (sim.winch().motion().acceleration == 0.0) {  // not where the winch's acceleration changes
        out.steady = std::max(out.steady, jump);
      }
      previous = snap.line_pull;
    }
  }
  out.links_added = sim.linksAdded();
  out.links_removed = sim.linksRemoved();
  out.retried = sim.retriedSteps();
  std::cout << stiffness << ", " << speed << " m/s: " << out.links_added << " links added, " << out.links_removed
            << " removed; the line pull jumps by at most " << 100.0 * out.added << " % where one is added, "
            << 100.0 * out.removed << " % where one is removed, " << 100.0 * out.steady
            << " % in any other step at a steady speed" << std::endl;
  return out;
}

const char* const kLimp = "{model: paper}";
const char* const kStiff = "{model: bending, bending_rigidity: 20.0, torsional_rigidity: 20.0}";

}  // namespace

// Adding a link at the winch keeps every material point's position and velocity (the split is exact in
// the state), and the new joint starts with the moment the rigid link held there (docs/MODEL.md section 8,
// "A link added"): the accelerations, and with them the line pull, go on. Removing one straightens the kink
// between the two links it merges. In a pay-out and haul-in in a current, at 0.1 and 1 m/s, for a limp
// cable and for a stiff one clamped at the base (EI = GJ = 20 N m^2), the line pull jumps in the step of a
// change by less than 2 % of itself (the requirement; measured at most 0.0005 % where a link is added,
// 1.15 % before the hold, and 0.003 % where one is removed), and by less than 0.1 % in any other step at
// a steady speed (measured 0.004 %). The line pull over the seconds after a link is added (issue 27's
// sawtooth): test_winch_line_pull.
TEST(Winch, AddingAndRemovingLinksDoesNotJumpTheLinePullInOneStep) {
  for (const char* stiffness : {kLimp, kStiff}) {
    for (const double speed : {0.1, 1.0}) {
      const PullJumps j = linePullJumps(stiffness, speed);
      EXPECT_GE(j.links_added, 8);
      EXPECT_GE(j.links_removed, 8);
      EXPECT_LT(j.added, 0.02) << stiffness << " at " << speed << " m/s";
      EXPECT_LT(j.removed, 2e-4) << stiffness << " at " << speed << " m/s";
      EXPECT_LT(j.steady, 1e-3) << stiffness << " at " << speed << " m/s";
      EXPECT_EQ(j.retried, 0);
    }
  }
}

// Paid out to twice its length and hauled back in, the cable settles back to the shape it started from.
TEST(Winch, PayingOutAndHaulingBackInReturnsToTheStart) {
  CableSimulator sim(inCurrent(0.0));
  run(sim, 60.0);
  SimulationSnapshot start, end;
  sim.snapshot(start);
  sim.commandWinchLength(40.0);
  run(sim, 60.0);
  EXPECT_NEAR(sim.deployedLength(), 40.0, 1e-3);
  sim.commandWinchLength(20.0);
  run(sim, 60.0);
  run(sim, 60.0);  // settle
  sim.snapshot(end);
  EXPECT_NEAR(end.deployed_length, 20.0, 1e-3);
  // The winch's link may now be longer than at the start (it is kept between 1 and 2.25 links): the
  // links beyond it are the same material, at the same arc length from the tip, in both.
  const int from = std::max(start.first_link, end.first_link) + 1;
  const int count = static_cast<int>(start.chain.ends.cols()) - from;
  const double tip = (end.chain.ends.rightCols(1) - start.chain.ends.rightCols(1)).norm();
  const double shape = (end.chain.ends.rightCols(count) - start.chain.ends.rightCols(count)).colwise().norm().maxCoeff();
  std::cout << "back at 20 m: tip " << tip << " m, worst link end " << shape << " m from the start; line pull "
            << end.line_pull << " N against " << start.line_pull << " N" << std::endl;
  EXPECT_LT(tip, 0.01);
  EXPECT_LT(shape, 0.01);
  EXPECT_NEAR(end.line_pull, start.line_pull, 1e-3 * start.line_pull);
}

TEST(Winch, AnOperatorsCommandReplacesTheSchedule) {
  // Issue 27: the schedule pays out from 0.5 s and hauls in from 3 s. The operator stops the winch at 1 s:
  // nothing of the schedule may follow (before, its haul-in started at 3 s); reset() plays it again.
  CableParams p = loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
      "load: {mass: 20.0, volume: 0.005}\n"
      "winch: {max_length: 30.0, min_length: 5.0, max_speed: 1.0, max_acceleration: 2.0, speed: 0.0,\n"
      "        schedule: [{time: 0.5, speed: 0.5}, {time: 3.0, speed: -0.5}]}\n"
      "simulation: {dt: 0.001}\n");
  CableSimulator sim(p);
  while (sim.time() < 1.0 - 1e-9) ASSERT_TRUE(sim.step().ok);
  EXPECT_NEAR(sim.winch().motion().speed, 0.5, 1e-9);  // the schedule's first command
  sim.commandWinchSpeed(0.0);
  while (sim.time() < 5.0 - 1e-9) ASSERT_TRUE(sim.step().ok);
  EXPECT_EQ(sim.winch().motion().speed, 0.0);  // the operator's stop holds past 3 s
  const double stopped = sim.deployedLength();
  while (sim.time() < 6.0 - 1e-9) ASSERT_TRUE(sim.step().ok);
  EXPECT_EQ(sim.deployedLength(), stopped);
  sim.reset();
  while (sim.time() < 1.0 - 1e-9) ASSERT_TRUE(sim.step().ok);
  EXPECT_NEAR(sim.winch().motion().speed, 0.5, 1e-9);  // reset plays the schedule again from t = 0
}

TEST(Winch, ResetToEquilibriumKeepsTheWinchRunning) {
  // Issue 27: hauling in at 1 m/s (max_acceleration 0.2 m/s^2), reset_to_equilibrium stopped the winch
  // within one step (-1.0 -> -0.0026 m/s in 10 ms) and then re-accelerated it. It keeps running now: one
  // step later its speed is within max_acceleration dt of what it was.
  CableParams p = loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
      "load: {mass: 20.0, volume: 0.005}\n"
      "winch: {max_length: 30.0, min_length: 5.0, max_speed: 1.0, max_acceleration: 0.2, speed: -1.0}\n"
      "simulation: {dt: 0.001}\n");
  p.winch.speed = 0.0;
  CableSimulator sim(p);
  sim.commandWinchSpeed(-1.0);
  while (sim.time() < 6.0 - 1e-9) ASSERT_TRUE(sim.step().ok);
  const double before = sim.winch().motion().speed;
  ASSERT_NEAR(before, -1.0, 1e-9);
  ASSERT_TRUE(sim.resetToEquilibrium().converged);
  ASSERT_TRUE(sim.step().ok);
  EXPECT_NEAR(sim.winch().motion().speed, before, 0.2 * sim.dt() + 1e-12);
}

// Issue 22: the model is constant after construction; the winch's deployment lives in the data. Paying out
// adds links (the data's first slot and winch link change) while every constant the model holds stays as
// built: the configured lengths and masses of every slot, and the load's. Before the split, the model's
// own per-link description was the deployed one and changed at every link added.
TEST(Winch, PayingOutChangesTheDataNotTheModel) {
  CableSimulator sim(lowering(1025.0, 1.0, 30.0));
  const ChainModel& model = sim.dynamics().model();
  const Eigen::VectorXd lengths = model.configured().length, masses = model.configured().mass;
  const LoadConstants load = model.load();
  const int first = sim.dynamics().deployed().firstLink();
  const double winch_link = sim.properties().length(first);
  for (int i = 0; i < 5000; ++i) ASSERT_TRUE(sim.step().ok);  // 5 s at 1 m/s: links of 2 m added
  EXPECT_LT(sim.dynamics().deployed().firstLink(), first);
  EXPECT_NE(sim.properties().length(sim.firstLink()), winch_link);
  EXPECT_EQ(model.configured().length, lengths);
  EXPECT_EQ(model.configured().mass, masses);
  EXPECT_EQ(model.load().inertia, load.inertia);
  EXPECT_EQ(model.load().weight, load.weight);
  // The deployed description is the data's: the drum's slots before the first carry nothing.
  EXPECT_EQ(sim.properties().mass.head(sim.firstLink()).sum(), 0.0);
  EXPECT_GT(masses.head(sim.firstLink()).sum(), 0.0);
}
