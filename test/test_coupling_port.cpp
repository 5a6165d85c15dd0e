// Issue 26: the ROV's port of an attached load, for an ROV simulator that couples implicitly. Its stiffness
// and damping against central differences of the wrench the simulator itself reports on the ROV
// (SimulationSnapshot::rov, about the ROV's origin in its axes, taken back to the attachment point here), and
// the first-order hold of an external target between poses.
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/end_conditions.h"

using namespace cable_dynamics;

namespace {

// A 20 m tether in a current, its tip 0.4 m off the ROV's origin, coupled at 20 kN/m and 2000 N s/m.
const char* const kTether =
    "cable: {links: 8, length: 20.0, diameter: 0.025, mass_per_length: 0.6}\n"
    "load: {mass: 5.0, volume: 0.002, mode: attached, attachment: [-0.4, 0.1, 0.2],\n"
    "       coupling: {stiffness: 20000.0, damping: 2000.0}}\n"
    "fluid: {density: 1025.0, current: [0.5, 0.2, 0.0]}\n"
    "simulation: {dt: 0.001}\n";

using Vector6 = Eigen::Matrix<double, 6, 1>;

/// The wrench on the ROV at its attachment point (world axes) after setting the target to `point`,
/// `velocity` and `attitude`, from the snapshot's wrench about the ROV's origin: M_point = M_origin - r x F.
Vector6 wrenchAtPoint(CableSimulator& sim, const Eigen::Vector3d& point, const Eigen::Vector3d& velocity,
                      const Eigen::Quaterniond& attitude, const Eigen::Vector3d& attachment) {
  sim.setLoadTarget(point, velocity, attitude);
  SimulationSnapshot s;
  sim.snapshot(s);
  const Eigen::Vector3d r = attitude * attachment;  // origin to attachment point, world axes
  Vector6 w;
  // The snapshot is in the paper frame; the ROV simulator sees world axes (as the node publishes them).
  const Eigen::Vector3d force = paperToWorld(s.rov.force), moment = paperToWorld(s.rov.moment);
  w << force, moment - r.cross(force);
  return w;
}

}  // namespace

TEST(CouplingPort, StiffnessAndDampingAreTheWrenchsDerivatives) {
  const CableParams params = loadConfigString(kTether);
  CableSimulator sim(params);
  for (int i = 0; i < 200; ++i) sim.step();  // away from rest: the tip moving, the coupling loaded
  SimulationSnapshot s;
  sim.snapshot(s);
  const Eigen::Vector3d tip = paperToWorld(s.chain.ends.col(params.links));
  // A state off the coupling's balance: the point 3 cm from the tip, moving.
  const Eigen::Vector3d point = tip + Eigen::Vector3d(0.02, -0.01, 0.02), velocity(0.3, -0.1, 0.05);
  const Eigen::Quaterniond attitude(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 0.5, 1.0).normalized()));
  const Vector6 w0 = wrenchAtPoint(sim, point, velocity, attitude, params.load.attachment);
  sim.snapshot(s);
  const CouplingPort port = portInWorldAxes(s.port);
  EXPECT_LT((port.point - point).norm(), 1e-12);
  EXPECT_LT((port.velocity - velocity).norm(), 1e-12);
  EXPECT_LT(((Vector6() << port.force, port.moment).finished() - w0).norm(), 1e-9 * w0.norm());
  // Central differences, step 1e-4 m (m/s, rad): the wrench is affine in the point and its velocity, so the
  // differences are exact to round-off (~1e-16 x 400 N / 1e-4 ~ 1e-9 N/m).
  const double h = 1e-4;
  Eigen::Matrix<double, 6, 6> stiffness, damping;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
    stiffness.col(j) = (wrenchAtPoint(sim, point + e, velocity, attitude, params.load.attachment) -
                        wrenchAtPoint(sim, point - e, velocity, attitude, params.load.attachment)) / (2.0 * h);
    damping.col(j) = (wrenchAtPoint(sim, point, velocity + e, attitude, params.load.attachment) -
                      wrenchAtPoint(sim, point, velocity - e, attitude, params.load.attachment)) / (2.0 * h);
    // A turn of the ROV about the attachment point (the point stays): its rotational column.
    const Eigen::Quaterniond plus(Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(j)) * attitude);
    const Eigen::Quaterniond minus(Eigen::AngleAxisd(-h, Eigen::Vector3d::Unit(j)) * attitude);
    stiffness.col(3 + j) = (wrenchAtPoint(sim, point, velocity, plus, params.load.attachment) -
                            wrenchAtPoint(sim, point, velocity, minus, params.load.attachment)) / (2.0 * h);
  }
  // Angular velocity: the node receives poses without rates, so the wrench does not depend on it.
  damping.rightCols<3>().setZero();
  const double k_error = (stiffness - port.stiffness).norm(), c_error = (damping - port.damping).norm();
  std::cout << "coupling port: |K - dW/dx| = " << k_error << " N/m of " << port.stiffness.norm() << ", |C - dW/dv| = "
            << c_error << " N s/m of " << port.damping.norm() << "\n";
  // Measured 4.7e-8 of 3.5e4 (1.3e-12) and 4.0e-10 of 3.5e3 (1.2e-13): the round-off of differences over
  // 2e-4 of a ~400 N wrench. Bounds about 8x those.
  EXPECT_LT(k_error, 1e-11 * port.stiffness.norm());
  EXPECT_LT(c_error, 1e-12 * port.damping.norm());
  EXPECT_NEAR(port.stiffness(0, 0), -20000.0, 1e-9);
  EXPECT_NEAR(port.damping(2, 2), -2000.0, 1e-9);
}

TEST(CouplingPort, ATargetMovesOnWithItsVelocityUntilTheHoldEnds) {
  CableSimulator sim(loadConfigString(kTether));
  const Eigen::Vector3d point(0.1, 0.2, -20.0), velocity(0.4, -0.2, 0.1);
  sim.setLoadTarget(point, velocity, Eigen::Quaterniond::Identity(), 0.0);
  SimulationSnapshot s;
  for (int i = 0; i < 100; ++i) sim.step();  // 0.1 s
  sim.snapshot(s);
  // p + v (t - t0): exact up to the sum of 100 steps of dt in the time (1e-15 s).
  EXPECT_LT((portInWorldAxes(s.port).point - (point + sim.time() * velocity)).norm(), 1e-12);
  EXPECT_LT((portInWorldAxes(s.port).velocity - velocity).norm(), 1e-15);
  // Past the hold's limit the point stops where the limit left it.
  for (int i = 0; i < 300; ++i) sim.step();  // t = 0.4 s > 0.25 s
  sim.snapshot(s);
  EXPECT_LT((portInWorldAxes(s.port).point - (point + EndConditions::kTargetExtrapolation * velocity)).norm(), 1e-12);
  EXPECT_EQ(s.port.velocity.norm(), 0.0);
}

TEST(CouplingPort, ZeroUnlessAttached) {
  CableSimulator sim(loadConfigString(
      "cable: {links: 4, length: 8.0, diameter: 0.02, mass_per_length: 0.5}\nload: {mass: 2.0, mode: free}\n"));
  SimulationSnapshot s;
  sim.snapshot(s);
  EXPECT_EQ(s.port.stiffness.norm() + s.port.damping.norm() + s.port.force.norm(), 0.0);
}
