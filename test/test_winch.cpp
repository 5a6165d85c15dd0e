// The winch at the base (docs/MODEL.md section 9): its speed and length law, and the cable it pays out
// and hauls in, against force balances and bookkeeping nobody here wrote: the line pull of a load lowered
// at constant speed (submerged weight of the deployed cable and the load, less the drag at that speed),
// the deployed length against the integral of the commanded speed, the mass against the length, and
// the energy balance with the winch's work and the paid-out cable's energy counted.
#include <cmath>
#include <iomanip>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
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
  EXPECT_NEAR(winch.motion().speed, 0.0, 1e-6);
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

TEST(Winch, ConfigAddsTheDrumsSlotsInFrontOfTheDeployedCable) {
  const CableParams p = lowering(1025.0, 0.5, 60.0);
  // 40 m more in 2 m links, and one more for the winch's link's band.
  EXPECT_EQ(p.winch.stored_links, 21);
  EXPECT_EQ(p.links, 31);
  EXPECT_DOUBLE_EQ(p.deployedLength(), 20.0);
  CableSimulator sim(p);
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
// the cable, 1/2 rho C_t pi d v^2 per metre), within 1 %; in air, the weight alone.
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
    EXPECT_LT(worst, 0.01);
    EXPECT_LT(length_error, 1e-6);
    EXPECT_LT(mass_error, 1e-9);
    EXPECT_GT(sim.linksAdded(), 10);
    EXPECT_LT(sim.energyDrift(), 1e-3);
    EXPECT_EQ(sim.retriedSteps(), 0);
  }
}
