// The joint efforts the node publishes (JointState effort = -spring_force, output_source.cpp) are the
// model's: with the base's clamp turning with a rolling, yawing vessel, they equal -dV/dq of the joint
// springs with the clamp where the dynamics have it at that instant. The truth: central differences of the
// dynamics' elastic energy on q with that clamp (test/spring_gradient.h). The node had rerun ElasticJoints
// with the clamp at rest (off by up to 189 N m where the springs' largest is 34 N m: test_written_once).
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/ros/output_source.h"
#include "../spring_gradient.h"

namespace cable_dynamics {
namespace {

TEST(PublishedEfforts, AreTheModelsWithATurningClamp) {
  const CableParams params = loadConfigString(
      "cable: {links: 10, length: 10.0, diameter: 0.05, mass_per_length: 2.0,\n"
      "        stiffness: {model: bending, bending_rigidity: 500.0, torsional_rigidity: 200.0}}\n"
      "load: {mass: 50.0}\n"
      "fluid: {density: 0.0}\n"
      "base: {motion: {period: 20.0, attitude_amplitude: [0.1, 0.05, 0.5]}}\n"
      "simulation: {dt: 0.0005}\n");
  CableSimulator sim(params);
  OutputSource source;
  source.spring_force = Eigen::VectorXd::Zero(3 * params.links);
  double worst = 0.0, largest = 0.0;
  for (int i = 1; i <= 8000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 1000 != 0) continue;
    ASSERT_TRUE(readOutputs(sim, source));
    // The springs with the clamp as the dynamics turned it for this state.
    const ChainData& data = sim.dynamics().data();
    const Eigen::VectorXd truth = springGradientByDifferences(params, source.snapshot.q, data.clamp_axis, data.clamp_twist);
    worst = std::max(worst, (source.spring_force - truth).lpNorm<Eigen::Infinity>());
    largest = std::max(largest, truth.lpNorm<Eigen::Infinity>());
  }
  std::cout << "published spring forces off the model's by at most " << worst << " N m, of up to " << largest << " N m"
            << std::endl;
  EXPECT_GT(largest, 1.0);  // the clamp does load the springs
  EXPECT_LT(worst, 6e-11 * largest);  // the differences' round-off: measured 1.1e-11 of it (3.8e-10 N m)
}

}  // namespace
}  // namespace cable_dynamics
