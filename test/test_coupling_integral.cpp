// Issue 26: the coupling's integral action (load.coupling.integral_time). A soft coupling, sized for a light
// ROV's exchange, lets the tip sit F / k from the ROV's point; near the tether's reach the pull there is not
// the pull at the ROV's point (rov_client.test: 8-12 % at 350 N/m). With the integral the spring's rest point
// moves until the tip is on the target, so at rest the coupling passes the force of a tip held at the point.
// The truth is the same cable held at the point by a coupling 1e5 times stiffer, at its equilibrium.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"

using namespace cable_dynamics;

namespace {

// A 20 m tether in a 0.5 m/s current, its tip coupled to a point 0.25 m inside its reach (the straight
// start bowed by 0.2 m up and 0.2 m in): near taut, where the pull changes fastest with the tip's place.
const char* const kTether =
    "cable: {links: 20, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
    "load: {mass: 10.0, volume: 0.005, mode: attached, coupling: {stiffness: 350.0, damping: 40.0},\n"
    "       motion: {offset: [-0.2, 0.0, 0.2]}}\n"
    "fluid: {density: 1025.0, current: [0.5, 0.0, 0.0]}\n"
    "initial: {mode: equilibrium, elevation: [1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]}\n"
    "simulation: {dt: 0.002}\n";

// The truth's hold: 1e5 times the soft spring, its tip F / k = 1.1e-6 m from the point (the implicit step's
// simulator, which no RK4 stable step refuses; only its statics are used).
const std::vector<std::string> kStiffHold = {"load.coupling.stiffness=3.5e7", "load.coupling.damping=4e4",
                                             "simulation.integrator=implicit"};

struct Held {
  Eigen::Vector3d force;      ///< on the ROV [N], paper frame
  Eigen::Vector3d tip_miss;   ///< tip - target [m]
};

Held held(CableSimulator& sim) {
  SimulationSnapshot s;
  sim.snapshot(s);
  return {s.port.force, s.chain.ends.col(sim.links()) - s.port.point};
}

double relative(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() / b.norm(); }

}  // namespace

// The equilibrium (resetToEquilibrium, which initial.mode equilibrium runs): the soft spring with the integral
// passes the stiff hold's force to 6e-7 of it with the tip 2.4e-7 m from the point (bounds 5e-6 and 1e-6 m, the
// statics passes' own tolerance); without the integral the same spring's force is 8.5 % off with the tip
// 0.11 m away, which the test requires to stay above 1 %: the integral must matter here.
TEST(CouplingIntegral, TheEquilibriumHoldsTheTipOnThePointWithTheStiffHoldsForce) {
  CableSimulator stiff(loadConfigString(kTether, kStiffHold));
  CableSimulator soft(loadConfigString(kTether));
  CableSimulator integral(loadConfigString(kTether, {"load.coupling.integral_time=2.0"}));
  const Held truth = held(stiff), plain = held(soft), with = held(integral);
  std::printf("[ integral ] force %.4f N held stiffly (tip %.2e m off); soft spring: %.4f N (%.2e off, tip %.3f m off); "
              "with the integral: %.4f N (%.2e off, tip %.2e m off)\n",
              truth.force.norm(), truth.tip_miss.norm(), plain.force.norm(), relative(plain.force, truth.force),
              plain.tip_miss.norm(), with.force.norm(), relative(with.force, truth.force), with.tip_miss.norm());
  EXPECT_LT(truth.tip_miss.norm(), 1e-3);
  EXPECT_GT(relative(plain.force, truth.force), 1e-2) << "the case does not show the soft spring's offset";
  EXPECT_LT(relative(with.force, truth.force), 5e-6);
  EXPECT_LT(with.tip_miss.norm(), 1e-6);
}

// From a start that is not the equilibrium (the straight line at 1 rad, released), both integrators carry the
// tip to the point and the force to the stiff hold's, every step accepted whole: after 60 s (30 integral
// times) the force 1.1e-6 off the truth's and the tip 6e-10 m off the point (bounds 1e-5 and 5e-9 m).
TEST(CouplingIntegral, TheDynamicsCarryTheTipToThePoint) {
  CableSimulator stiff(loadConfigString(kTether, kStiffHold));
  const Held truth = held(stiff);
  for (const char* integrator : {"rk4", "implicit"}) {
    SCOPED_TRACE(integrator);
    CableSimulator sim(loadConfigString(kTether, {"load.coupling.integral_time=2.0", "initial.mode=angles",
                                                  std::string("simulation.integrator=") + integrator}));
    for (int i = 0; i < 30000; ++i) {
      const StepReport r = sim.step();
      ASSERT_TRUE(r.ok && r.substeps == 1) << "step " << i << ": " << r.message;
    }
    const Held end = held(sim);
    std::printf("[ integral ] %s after 60 s: force %.2e off the stiff hold's, tip %.2e m off the point\n", integrator,
                relative(end.force, truth.force), end.tip_miss.norm());
    EXPECT_LT(relative(end.force, truth.force), 1e-5);
    EXPECT_LT(end.tip_miss.norm(), 5e-9);
  }
}

// Anti-windup: a target beyond the tether's reach (the start's tip moved 2 m out and 1.2 m down: the tip
// ends 0.9 m short of it) is one the tip never gets to. The integral holds its shift there, so the force is the plain spring's at the miss
// it holds: after 60 s equal to the run without the integral (to 1e-9 of it; both start from the same angles
// with the shift at zero), where integrating the 0.9 m miss would have added k 0.9 m 60 s / 2 s = 9.4 kN.
TEST(CouplingIntegral, ATargetBeyondReachDoesNotWindTheForceUp) {
  const std::vector<std::string> beyond = {"initial.mode=angles", "load.motion={offset: [2.0, 0.0, -1.2]}"};
  std::vector<std::string> with_integral = beyond;
  with_integral.push_back("load.coupling.integral_time=2.0");
  CableSimulator plain(loadConfigString(kTether, beyond)), integral(loadConfigString(kTether, with_integral));
  for (int i = 0; i < 30000; ++i) {
    ASSERT_TRUE(plain.step().ok);
    ASSERT_TRUE(integral.step().ok);
  }
  const Held a = held(plain), b = held(integral);
  std::printf("[ integral ] target beyond reach: tip %.3f m off it, force %.2f N without the integral, %.2f N with\n",
              a.tip_miss.norm(), a.force.norm(), b.force.norm());
  EXPECT_GT(a.tip_miss.norm(), 0.5);
  EXPECT_LT(relative(b.force, a.force), 1e-9);
}
