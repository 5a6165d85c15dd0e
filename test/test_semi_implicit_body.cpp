// The semi-implicit step with an ROV body (issue 26: the body under every integrator): an 11.5 kg ROV on
// a light 16 m tether in a current, against the same case stepped by RK4 at 0.5 ms (whose model
// test_rov_body and test_chain_dynamics hold against closed forms and the dense formulation). The step
// must converge to it at first order in dt.
// Not held here, a fault of the semi-implicit step with or without a body (docs/MODEL.md section 6):
// from 2.5 ms up this case diverges (the light links' spin runs away), as a point load on it does.
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "light_tether_rov.h"

using namespace cable_dynamics;

namespace {

/// The link ends every 0.5 s over 10 s [m], and the steps that needed substeps.
std::vector<Eigen::Matrix3Xd> linkEnds(const std::string& simulation, long& retried) {
  CableSimulator sim(loadConfigString(std::string(cable_dynamics_test::kLightTetherRov) + "simulation: {" + simulation + "}\n"));
  std::vector<Eigen::Matrix3Xd> out;
  SimulationSnapshot s;
  const long steps = std::lround(10.0 / sim.dt()), every = std::lround(0.5 / sim.dt());
  for (long i = 1; i <= steps; ++i) {
    const StepReport r = sim.step();
    EXPECT_TRUE(r.ok) << simulation << " at t = " << sim.time();
    if (!r.ok) break;
    if (i % every == 0) {
      sim.snapshot(s);
      out.push_back(s.chain.ends);
    }
  }
  retried = sim.retriedSteps();
  return out;
}

double largestDifference(const std::vector<Eigen::Matrix3Xd>& a, const std::vector<Eigen::Matrix3Xd>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, (a[i] - b[i]).cwiseAbs().maxCoeff());
  return worst;
}

}  // namespace

TEST(SemiImplicitBody, ConvergesToRk4AtFirstOrder) {
  long retried = 0;
  const auto reference = linkEnds("integrator: rk4, dt: 0.0005", retried);
  const auto coarse = linkEnds("integrator: semi_implicit, dt: 0.002", retried);
  EXPECT_EQ(retried, 0);
  const auto fine = linkEnds("integrator: semi_implicit, dt: 0.001", retried);
  EXPECT_EQ(retried, 0);
  const double e_coarse = largestDifference(coarse, reference), e_fine = largestDifference(fine, reference);
  const double order = std::log2(e_coarse / e_fine);
  std::cout << "[ semi-implicit ] largest link-end difference from RK4 over 10 s: " << e_coarse << " m at 2 ms, "
            << e_fine << " m at 1 ms (order " << order << ")\n";
  // Measured: 3.15e-4 m at 2 ms, 1.63e-4 m at 1 ms (order 0.95). Bounds: 2e-3 m at 2 ms (6x), the order
  // between 0.7 and 1.3 (first order; a body the step held wrongly would not converge).
  EXPECT_LT(e_coarse, 2e-3);
  EXPECT_GT(order, 0.7);
  EXPECT_LT(order, 1.3);
}
