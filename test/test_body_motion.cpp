// The ends as bodies (issue 14, items 1 and 2): a vessel's attitude moves the hang-off point on its arc,
// the cable's force there puts a moment r x F on the vessel, and the tether's attachment off the ROV's
// centre puts a moment offset x F on the ROV. Against closed forms: rotation about an axis keeps a point
// on its circle, finite differences of the attitude, and the cross product itself.
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/body_motion.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "refused_key.h"

using namespace cable_dynamics;

namespace {

MotionParams rolling(double roll, double pitch, double yaw) {
  MotionParams m;
  m.period = 8.0;
  m.attitude_amplitude = Eigen::Vector3d(roll, pitch, yaw);
  m.attitude_phase = Eigen::Vector3d(0.3, 1.1, -0.4);
  return m;
}

const char* const kCable =
    "cable: {links: 10, length: 30.0, diameter: 0.025, mass_per_length: 0.6}\n"
    "load: {mass: 20.0, volume: 0.005}\n"
    "fluid: {density: 0.0}\n"
    "simulation: {dt: 0.001}\n";

}  // namespace

TEST(BodyMotion, AttitudeRatesAreTheDerivativesOfTheAttitude) {
  const MotionParams m = rolling(0.2, 0.1, 0.3);
  const double h = 1e-5;
  for (double t : {0.0, 0.7, 3.1}) {
    Eigen::Matrix3d r, dr, ddr, rp, drp, ddrp, rm, drm, ddrm;
    attitudeAt(m, t, r, dr, ddr);
    attitudeAt(m, t + h, rp, drp, ddrp);
    attitudeAt(m, t - h, rm, drm, ddrm);
    EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    // Central differences: truncation ~ h^2 |R'''| ~ 1e-10, round-off ~ 1e-16 / h ~ 1e-11.
    EXPECT_LT((dr - (rp - rm) / (2.0 * h)).norm(), 1e-8);
    EXPECT_LT((ddr - (drp - drm) / (2.0 * h)).norm(), 1e-8);
  }
}

TEST(BodyMotion, APureRollMovesTheHangOffPointOnItsArc) {
  const MotionParams m = rolling(0.25, 0.0, 0.0);
  const Eigen::Vector3d hang_off(3.0, 5.0, 10.0);  // aft of the origin, to starboard... and up, vessel frame
  const double radius = std::hypot(hang_off.y(), hang_off.z());
  double worst_radius = 0.0, worst_x = 0.0, worst_angle = 0.0;
  for (double t = 0.0; t < 8.0; t += 0.05) {
    Eigen::Vector3d p, v, a;
    bodyPointAt(m, hang_off, t, p, v, a);
    const Eigen::Vector3d point = hang_off + p;  // from the vessel's origin
    worst_radius = std::max(worst_radius, std::abs(std::hypot(point.y(), point.z()) - radius));
    worst_x = std::max(worst_x, std::abs(point.x() - hang_off.x()));
    // Its angle about x is the roll angle.
    const double roll = 0.25 * std::sin(2.0 * M_PI * t / 8.0 + 0.3);
    const double angle = std::atan2(point.z(), point.y()) - std::atan2(hang_off.z(), hang_off.y());
    worst_angle = std::max(worst_angle, std::abs(angle - roll));
    EXPECT_NEAR(v.dot(point - Eigen::Vector3d(point.x(), 0.0, 0.0)), 0.0, 1e-12);  // tangent to the circle
  }
  EXPECT_LT(worst_radius, 1e-12);
  EXPECT_LT(worst_x, 1e-12);
  EXPECT_LT(worst_angle, 1e-12);
}

TEST(BodyMotion, TheCablesBaseFollowsTheHangOffPointAndTheMomentIsRCrossF) {
  CableSimulator sim(loadConfigString(
      kCable, {"base.hang_off=[-4.0, 6.0, 8.0]", "base.motion={period: 6.0, attitude_amplitude: [0.15, 0.05, 0.1]}"}));
  SimulationSnapshot snap;
  double worst_base = 0.0, worst_moment = 0.0, worst_body = 0.0;
  const Eigen::Vector3d r(-4.0, 6.0, 8.0);
  for (int i = 1; i <= 6000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 200 != 0) continue;
    sim.snapshot(snap);
    Eigen::Vector3d p, v, a;
    MotionParams m;
    m.period = 6.0;
    m.attitude_amplitude = Eigen::Vector3d(0.15, 0.05, 0.1);
    bodyPointAt(m, r, sim.time(), p, v, a);
    worst_base = std::max(worst_base, (paperToWorld(snap.chain.ends.col(0)) - p).norm());
    const Eigen::Matrix3d rotation = paperToWorldAttitude(snap.vessel_attitude).toRotationMatrix();  // world from vessel
    const Eigen::Vector3d force = paperToWorld(snap.chain.base_force);
    const Eigen::Vector3d lever = rotation * r;
    const Eigen::Vector3d moment(lever.y() * force.z() - lever.z() * force.y(), lever.z() * force.x() - lever.x() * force.z(),
                                 lever.x() * force.y() - lever.y() * force.x());
    worst_moment = std::max(worst_moment, (paperToWorld(snap.vessel.moment) - moment).norm() / (lever.norm() * force.norm()));
    const Eigen::Vector3d body_force = rotation.transpose() * force;
    worst_body = std::max(worst_body, (snap.vessel.moment_body - r.cross(body_force)).norm() / (r.norm() * force.norm()) +
                                          (snap.vessel.force_body - body_force).norm() / force.norm());
  }
  std::cout << "base off the hang-off point by " << worst_base << " m; moment off r x F by " << worst_moment
            << " (world), " << worst_body << " (vessel frame), relative; energy drift " << sim.energyDrift() << std::endl;
  EXPECT_LT(worst_base, 1e-12);
  EXPECT_LT(worst_moment, 1e-14);
  EXPECT_LT(worst_body, 1e-14);
  // The vessel's rolling drives the cable through the moving hang-off point: the base's work keeps the
  // energy balance closed.
  EXPECT_LT(sim.energyDrift(), 1e-6);
  EXPECT_EQ(sim.retriedSteps(), 0);
}

// The snapshot is in one frame, the paper frame (issue 22): its bodies sit on the cable's ends with no
// conversion (the vessel's origin plus its turned hang-off offset is the base end; the ROV's origin plus
// its turned attachment offset is the coupling's target), and their wrenches are the cable's end forces
// in the same axes. Before, the bodies were in the world frame (z up) and the cable in the paper frame.
TEST(BodyMotion, TheSnapshotsBodiesAreInThePaperFrameWithTheCable) {
  CableSimulator sim(loadConfigString(
      kCable, {"base.hang_off=[-4.0, 6.0, 8.0]", "base.motion={period: 6.0, attitude_amplitude: [0.15, 0.05, 0.1]}",
               "load.mode=attached", "load.attachment=[-1.2, 0.0, 0.4]",
               "load.motion={period: 10.0, offset: [3.0, 0.0, 2.0], attitude_amplitude: [0.0, 0.2, 0.5]}"}));
  SimulationSnapshot s;
  double worst_point = 0.0, worst_force = 0.0;
  for (int i = 1; i <= 2000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 200 != 0) continue;
    sim.snapshot(s);
    const Eigen::Vector3d hang_off = s.vessel_origin + s.vessel_attitude * Eigen::Vector3d(-4.0, 6.0, 8.0);
    const Eigen::Vector3d attachment = s.rov_origin + s.rov_attitude * Eigen::Vector3d(-1.2, 0.0, 0.4);
    worst_point = std::max({worst_point, (hang_off - s.chain.ends.col(0)).norm(), (attachment - s.port.point).norm()});
    worst_force = std::max({worst_force, (s.vessel.force - s.chain.base_force).norm() / s.chain.base_force.norm(),
                            (s.rov.force + s.chain.coupling_force).norm() / s.chain.coupling_force.norm()});
  }
  // Measured 6.8e-16 m, the round-off of a rotation of a 10 m offset: bound 5e-15 m (7x). A world-frame
  // body beside the paper-frame cable puts them metres apart. The forces are the same numbers: exact.
  std::cout << "bodies on the cable's ends: " << worst_point << " m apart, forces off by " << worst_force << std::endl;
  EXPECT_LT(worst_point, 5e-15);
  EXPECT_EQ(worst_force, 0.0);
  // The node turns an attitude back to the world frame: the same quaternion as the input, sign included
  // (a sign flip is the same rotation, but a client comparing components sees it).
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.2, 0.9).normalized()));
  EXPECT_EQ((paperToWorldAttitude(worldToPaperAttitude(q)).coeffs() - q.coeffs()).norm(), 0.0);
}

TEST(BodyMotion, TheAttachmentPutsAMomentOnTheRov) {
  // An ROV pitching and yawing with the tether 1.2 m aft of and 0.4 m above its centre.
  CableSimulator sim(loadConfigString(
      kCable, {"load.mode=attached", "load.attachment=[-1.2, 0.0, 0.4]",
               "load.motion={period: 10.0, offset: [3.0, 0.0, 2.0], attitude_amplitude: [0.0, 0.2, 0.5]}"}));
  SimulationSnapshot snap;
  double worst = 0.0;
  const Eigen::Vector3d a(-1.2, 0.0, 0.4);
  for (int i = 1; i <= 5000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 250 != 0) continue;
    sim.snapshot(snap);
    const Eigen::Vector3d force = -paperToWorld(snap.chain.coupling_force);  // the coupling's reaction on the ROV
    const Eigen::Vector3d body = paperToWorldAttitude(snap.rov_attitude).conjugate() * force;
    worst = std::max(worst, (snap.rov.moment_body - a.cross(body)).norm() / (a.norm() * body.norm()) +
                                (snap.rov.force_body - body).norm() / body.norm());
  }
  std::cout << "ROV moment off offset x F by " << worst << " relative; the tip pulls " << snap.rov.force_body.transpose()
            << " N (ROV frame)" << std::endl;
  EXPECT_LT(worst, 1e-14);
  EXPECT_GT(snap.rov.moment_body.norm(), 1.0);
}

namespace {

/// A stiff 10 m cable (EI and GJ given) from a clamp on the vessel, in air, n links.
CableParams stiffOnVessel(int n, const std::vector<std::string>& extra) {
  std::vector<std::string> o = {"cable.links=" + std::to_string(n), "fluid.density=0"};
  o.insert(o.end(), extra.begin(), extra.end());
  return loadConfigString(
      "cable: {links: 10, length: 10.0, diameter: 0.05, mass_per_length: 2.0,\n"
      "        stiffness: {model: bending, bending_rigidity: 736000, torsional_rigidity: 500000}}\n"
      "simulation: {dt: 0.0005}\n",
      o);
}

}  // namespace

// The clamp turns with the vessel. A horizontal clamp (an I-tube along the vessel's x) on a vessel yawed
// by 90 degrees holds a cantilever along the world's y: its static tip deflection is w L^4 / (8 EI) as
// for the clamp at rest (1e-3 of L, geometry linear), and a run from that shape stays there.
TEST(BodyMotion, TheClampTurnsWithTheVessel) {
  const double ei = 7.36e5, w = 2.0 * 9.81, length = 10.0, exact = w * std::pow(length, 4) / (8.0 * ei);
  // Yaw (pi/2) sin(2 pi t / T + pi/2) with T = 1e6 s: 90 degrees, constant over the test to 1e-10 rad.
  // n = 20 (0.25 % off the closed form at rest, second order); dt below the bend springs' stable step.
  CableSimulator sim(stiffOnVessel(
      20, {"base.direction=[1, 0, 0]", "initial.mode=equilibrium", "simulation.dt=5e-5",
           "cable.stiffness={model: bending, bending_rigidity: 736000, torsional_rigidity: 10.0}",
           "base.motion={period: 1.0e6, attitude_amplitude: [0, 0, 1.5707963267948966], attitude_phase: [0, 0, 1.5707963267948966]}"}));
  SimulationSnapshot s;
  sim.snapshot(s);
  const Eigen::Vector3d tip = paperToWorld(s.chain.ends.col(sim.links()));
  std::cout << "yawed vessel's horizontal clamp: tip at " << tip.transpose() << " m; w L^4/(8 EI) = " << exact << " m"
            << std::endl;
  EXPECT_NEAR(tip.x(), 0.0, 1e-6);          // not along the world's x any more
  EXPECT_NEAR(tip.y(), length, 1e-3);       // along the vessel's x, which now points along the world's y
  EXPECT_NEAR(-tip.z() / exact, 1.0, 0.005);  // second order in n, as the clamp at rest (test_end_fixity)
  EXPECT_LE(sim.dt(), sim.estimateStableTimeStep());
  double wander = 0.0;
  for (int i = 0; i < 5000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 250 != 0) continue;
    sim.snapshot(s);
    wander = std::max(wander, (paperToWorld(s.chain.ends.col(sim.links())) - tip).norm());
  }
  EXPECT_LT(wander, 1e-4) << "the dynamics' clamp is not the statics' one";
  EXPECT_EQ(sim.retriedSteps(), 0);
}

// A rolling, pitching, yawing vessel drives a stiff cable through its turning clamp: the clamp's torque
// does work at the vessel's angular velocity, and with it counted the energy balance stays closed; the
// cable's twist follows the vessel's yaw (GJ holds it), the first link's sigma within 1e-2 rad of the
// clamp's psi_c + yaw.
TEST(BodyMotion, ATurningClampDoesWorkAndTwistsTheCable) {
  CableSimulator sim(stiffOnVessel(
      10, {"cable.stiffness={model: bending, bending_rigidity: 500.0, torsional_rigidity: 200.0}", "simulation.dt=0.0005",
           "base.motion={period: 20.0, attitude_amplitude: [0.1, 0.05, 0.5]}", "load.mass=50.0"}));
  SimulationSnapshot s;
  double worst_twist = 0.0, worst_moment = 0.0;
  for (int i = 1; i <= 40000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    if (i % 1000 != 0) continue;
    sim.snapshot(s);
    const double yaw = 0.5 * std::sin(2.0 * M_PI * sim.time() / 20.0);
    worst_twist = std::max(worst_twist, std::abs(s.twists(0) - yaw));
    // The vessel's moment: r x F of the hang-off point (at the origin here) and the clamp's reaction.
    const Eigen::Vector3d expected = -paperToWorld(sim.dynamics().data().clamp_torque);
    worst_moment = std::max(worst_moment, (paperToWorld(s.vessel.moment) - expected).norm() / (1e-12 + expected.norm()));
  }
  EXPECT_LT(worst_moment, 1e-12);
  EXPECT_LE(sim.dt(), sim.estimateStableTimeStep());
  std::cout << "turning clamp: energy drift " << sim.energyDrift() << ", first link's twist off the yaw by at most "
            << worst_twist << " rad, work input " << s.work_input << " J" << std::endl;
  EXPECT_LT(sim.energyDrift(), 1e-6);
  EXPECT_LT(worst_twist, 1e-2);
  EXPECT_EQ(sim.retriedSteps(), 0);
}

// A clamped tip on a pitching and yawing ROV (load.fixity: clamped, the direction in the ROV's frame):
// the clamp's axis turns with the ROV, its bend spring works on the cable (counted as the ends' work),
// so the energy balance closes; the ROV's moment is the attachment's offset x F plus the clamp's reaction
// torque; and the last link follows the clamp's direction to within a small bend.
TEST(BodyMotion, AClampedTipTurnsWithTheRovAndItsTorqueIsInTheRovsMoment) {
  // The balance's drift is RK4's (measured: it falls about 16x when dt halves), not a missing work term.
  double drift[2] = {0.0, 0.0};
  for (int run = 0; run < 2; ++run) {
    const double dt = run == 0 ? 0.0005 : 0.00025;
    CableSimulator sim(stiffOnVessel(
        10, {"cable.stiffness={model: bending, bending_rigidity: 500.0, torsional_rigidity: 200.0}",
             "simulation.dt=" + std::to_string(dt), "load.mode=attached", "load.mass=5.0", "load.fixity=clamped",
             "load.direction=[0.0, 0.0, -1.0]", "load.attachment=[-0.5, 0.0, 0.3]",
             "load.motion={period: 10.0, offset: [0.5, 0.0, 0.2], attitude_amplitude: [0.0, 0.2, 0.5]}"}));
    SimulationSnapshot s;
    double worst_moment = 0.0, worst_bend = 0.0, largest_clamp = 0.0;
    const Eigen::Vector3d a(-0.5, 0.0, 0.3);
    const long steps = std::lround(10.0 / dt), every = std::lround(0.25 / dt);
    for (long i = 1; i <= steps; ++i) {
      ASSERT_TRUE(sim.step().ok);
      if (i % every != 0) continue;
      sim.snapshot(s);
      const Eigen::Quaterniond rov_attitude = paperToWorldAttitude(s.rov_attitude);  // world from ROV
      const Eigen::Vector3d clamp_world = rov_attitude * Eigen::Vector3d(0.0, 0.0, -1.0);
      const Eigen::Vector3d last_axis = paperToWorld(s.axes.col(9));
      worst_bend = std::max(worst_bend, std::acos(std::min(1.0, last_axis.dot(clamp_world))));
      // offset x F with F the coupling's reaction, plus minus the torque the clamp holds the last link with.
      const Eigen::Vector3d force = -paperToWorld(s.chain.coupling_force);
      const Eigen::Vector3d clamp_torque = -paperToWorld(sim.dynamics().data().tip_clamp_torque);
      largest_clamp = std::max(largest_clamp, clamp_torque.norm());
      const Eigen::Vector3d expected = (rov_attitude * a).cross(force) + clamp_torque;
      worst_moment = std::max(worst_moment, (paperToWorld(s.rov.moment) - expected).norm() / expected.norm());
    }
    drift[run] = sim.energyDrift();
    std::cout << "clamped tip, dt " << dt << ": energy drift " << drift[run] << ", last link off the clamp by at most "
              << worst_bend << " rad, clamp torque up to " << largest_clamp << " N m, moment off by " << worst_moment
              << std::endl;
    EXPECT_LT(worst_moment, 1e-12);
    EXPECT_GT(largest_clamp, 1.0);  // the clamp does hold the cable (1000 N m/rad: 2 EI / l)
    EXPECT_EQ(sim.retriedSteps(), 0);
  }
  EXPECT_LT(drift[0], 1e-5);
  EXPECT_GT(drift[0] / drift[1], 8.0);  // at least third order: RK4's error, no energy source
}

TEST(BodyMotion, AClampedTipNeedsAnAnchorOrAnRovAndTheBendingModel) {
  const std::string cable = "cable: {links: 4, length: 4.0, diameter: 0.02, mass_per_length: 1.0, stiffness: {model: bending}}\n";
  auto key = [&](const std::string& extra) { return refusedKey(cable + extra); };
  EXPECT_EQ(key("load: {mode: anchored, fixity: clamped, direction: [1, 0, 0]}\n"), "(accepted)");
  EXPECT_EQ(key("load: {mode: free, fixity: clamped}\n"), "load.fixity");
  EXPECT_EQ(key("load: {mode: attached, fixity: welded}\n"), "load.fixity");
  EXPECT_EQ(key("load: {mode: attached, fixity: clamped, direction: [0, 0, 0]}\n"), "load.direction");
  try {
    loadConfigString("cable: {links: 4, length: 4.0, diameter: 0.02, mass_per_length: 1.0}\n"  // the paper model
                     "load: {mode: attached, fixity: clamped}\n");
    ADD_FAILURE() << "a clamped tip with the paper's springs was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "load.fixity");
  }
  // The clamp's spring: 2 EI / l_n, the half link to the tip.
  const CableParams p = loadConfigString(
      "cable: {links: 4, length: 4.0, diameter: 0.02, mass_per_length: 1.0, stiffness: {model: bending, bending_rigidity: 30.0}}\n"
      "load: {mode: anchored, fixity: clamped, direction: [1, 0, 0]}\n");
  const LinkProperties props = deriveLinkProperties(p);
  EXPECT_DOUBLE_EQ(props.tip_clamp_stiffness, 60.0);
  EXPECT_NEAR((props.tip_clamp_axis - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-15);
}
