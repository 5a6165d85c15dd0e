// The node's winch parts without a roscore: the winch/speed guard, the winch/set_length range check, the
// messages shaped for the deployed slots (names kept per slot, moved without allocating), cable_state's
// winch fields and the diagnostics' winch values, filled from a simulator that pays out and hauls in.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <new>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/state_layout.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/ros/finite_messages.h"
#include "cable_dynamics/ros/input_guard.h"
#include "cable_dynamics/ros/message_builders.h"
#include "cable_dynamics/ros/reset_request.h"
#include "cable_dynamics/ros/winch_request.h"

// Counts heap allocations while g_counting is set (this test binary only).
#include "../allocation_counter.h"

namespace cable_dynamics {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

/// test/node/winch_test.yaml without its `ros:` section: 10 links of 2 m deployed, up to 40 m (21 slots),
/// as the node holds it (the simulator's copy, with the drum's slots: CableSimulator::params()).
CableParams winchParams() {
  return ChainModel::withDrumSlots(loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.03, mass_per_length: 1.5}\n"
      "load: {mass: 40.0, volume: 0.01, drag_area: 0.1}\n"
      "simulation: {dt: 0.001}\n"
      "winch: {max_length: 40.0, min_length: 6.0, max_speed: 2.0, max_acceleration: 1.0}\n"));
}

CableFrameNames prefixed() {
  CableFrameNames names;
  names.prefix = "winch_test/";  // long enough that every name is on the heap (no small-string buffer)
  return names;
}

TEST(WinchGuard, SpeedsAreRefusedWithoutAWinchWhenNotFiniteOrBeyondMaxSpeed) {
  std_msgs::Float64 m;
  double speed = -7.0;
  InputGuard none{GuardSettings()};
  m.data = 0.5;
  EXPECT_EQ(none.winchSpeed(m, speed), InputVerdict::kNoWinch);
  EXPECT_EQ(speed, -7.0);
  EXPECT_EQ(none.counters().received, 1u);
  EXPECT_EQ(none.counters().rejected, 1u);
  EXPECT_NE(std::string(describe(InputVerdict::kNoWinch)).find("no winch is configured"), std::string::npos);

  GuardSettings s;
  s.winch = true;
  s.winch_max_speed = 2.0;
  InputGuard guard(s);
  for (double ok : {0.5, -2.0, 2.0, 0.0, -1e-300}) {
    m.data = ok;
    EXPECT_EQ(guard.winchSpeed(m, speed), InputVerdict::kAccepted) << ok;
    EXPECT_EQ(speed, ok);
  }
  m.data = 2.0000001;  // beyond max_speed: refused, not clamped
  EXPECT_EQ(guard.winchSpeed(m, speed), InputVerdict::kOutOfRange);
  m.data = -1e308;
  EXPECT_EQ(guard.winchSpeed(m, speed), InputVerdict::kOutOfRange);
  for (double bad : {kNan, kInf, -kInf}) {
    m.data = bad;
    EXPECT_EQ(guard.winchSpeed(m, speed), InputVerdict::kNonFinite) << bad;
  }
  EXPECT_EQ(speed, -1e-300) << "a refused command changed the speed handed on";
  EXPECT_EQ(guard.counters().received, 10u);
  EXPECT_EQ(guard.counters().rejected, 5u);
  EXPECT_EQ(guard.counters().stale, 0u);
}

TEST(WinchRequest, LengthsOutsideTheRangeAreRefusedNamingIt) {
  const CableParams p = winchParams();
  std::string why;
  for (double ok : {6.0, 25.0, 40.0}) EXPECT_TRUE(checkWinchLength(ok, p.winch, why)) << ok;
  for (double bad : {5.999, 40.001, -1.0, kNan, kInf}) {
    EXPECT_FALSE(checkWinchLength(bad, p.winch, why)) << bad;
    EXPECT_NE(why.find("[6, 40] m"), std::string::npos) << why;
  }
  const CableParams fixed = loadConfigString("cable: {links: 2, length: 2.0, diameter: 0.02, mass_per_length: 1.0}");
  EXPECT_FALSE(checkWinchLength(1.0, fixed.winch, why));
  EXPECT_EQ(why, kNoWinchMessage);
  EXPECT_NE(why.find("no winch"), std::string::npos);
}

TEST(WinchReset, TheDrumsSlotsMustBeZero) {
  const CableParams p = winchParams();
  const int drum = p.winch.stored_links;
  std::vector<double> q(3 * p.links, 0.0), qd;
  for (int k = drum; k < p.links; ++k) q[3 * k] = 0.3;  // the deployed links tilted
  std::string why;
  EXPECT_TRUE(checkResetRequest(q, qd, p.links, prefixed(), why, drum));
  q[3 * (drum - 1) + 1] = 0.1;  // the last drum slot's azimuth would turn the deployed cable
  EXPECT_FALSE(checkResetRequest(q, qd, p.links, prefixed(), why, drum));
  EXPECT_NE(why.find("positions[31] (winch_test/joint_11_azimuth) = 0.1: expected 0"), std::string::npos) << why;
  EXPECT_TRUE(checkResetRequest(q, qd, p.links, prefixed(), why, 0)) << "without a winch every slot is free";
  q[3 * (drum - 1) + 1] = 0.0;
  qd.assign(3 * p.links, 0.0);
  qd[0] = 1.0;
  EXPECT_FALSE(checkResetRequest(q, qd, p.links, prefixed(), why, drum));
  EXPECT_NE(why.find("velocities[0]"), std::string::npos) << why;
}

TEST(WinchOutputs, PreparedForTheConfiguredDeploymentWithNamesPerSlot) {
  const CableParams p = winchParams();
  ASSERT_EQ(p.links, 21);
  ASSERT_EQ(p.winch.stored_links, 11);
  CableOutputs o;
  prepareOutputs(p, prefixed(), "world", o);
  EXPECT_EQ(o.first_link, 11);
  ASSERT_EQ(o.joints.name.size(), 30u);
  EXPECT_EQ(o.joints.position.size(), 30u);
  EXPECT_EQ(o.joints.name[0], "winch_test/joint_12_elevation");
  EXPECT_EQ(o.joints.name.back(), "winch_test/joint_21_torsion");
  ASSERT_EQ(o.transforms.size(), 32u);
  EXPECT_EQ(o.transforms[0].child_frame_id, "winch_test/cable_paper");
  EXPECT_EQ(o.transforms[1].child_frame_id, "winch_test/link_12");
  EXPECT_EQ(o.transforms[2].child_frame_id, "winch_test/link_12_azimuth");
  EXPECT_EQ(o.transforms.back().child_frame_id, "winch_test/cable_load");
  EXPECT_EQ(o.markers.markers[0].points.size(), 11u);
  EXPECT_EQ(o.state.tension.size(), 21u);  // one entry per slot
  EXPECT_EQ(o.stowed_joint_names.size(), 33u);
  EXPECT_EQ(o.stowed_transforms.size(), 33u);
  EXPECT_TRUE(allFinite(o));
  // Without a winch: every slot, as before.
  CableOutputs plain;
  prepareOutputs(loadConfigString("cable: {links: 3, length: 3.0, diameter: 0.02, mass_per_length: 1.0}"),
                 prefixed(), "world", plain);
  EXPECT_EQ(plain.joints.name.size(), 9u);
  EXPECT_EQ(plain.transforms.size(), 11u);
  // 13 values, the winch's 7 with a winch, and the limits' 3 last.
  EXPECT_EQ(plain.diagnostics.status[0].values.size(), 16u);
  EXPECT_EQ(o.diagnostics.status[0].values.size(), 23u);
}

TEST(WinchOutputs, ShapingMovesNamesBetweenTheMessagesAndTheDrumWithoutAllocating) {
  const CableParams p = winchParams();
  CableOutputs o;
  prepareOutputs(p, prefixed(), "world", o);
  const std::vector<std::string> at_start = o.joints.name;
  const std::string* names = o.joints.name.data();
  const char* buffer = o.joints.name[0].c_str();  // "winch_test/joint_12_elevation", on the heap
  const auto shape = [&](int first) {
    g_allocations = 0;
    g_counting = true;
    shapeOutputs(first, o);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "shapeOutputs(" << first << ") allocated";
  };
  {  // the counter sees a copied name
    g_allocations = 0;
    g_counting = true;
    const std::string copy = at_start[0];
    g_counting = false;
    ASSERT_EQ(g_allocations, 1) << copy;
  }
  shape(8);  // three links paid out
  const std::size_t paid_out = o.joints.name.size(), frames_out = o.transforms.size();
  const std::string first_out = o.joints.name[0], frame_out = o.transforms[1].child_frame_id;
  const char* moved = o.joints.name[9].c_str();
  shape(15);  // seven hauled in
  const std::size_t hauled_in = o.joints.name.size();
  shape(0);   // every slot out
  shape(20);  // only the tip link
  shape(11);  // back
  EXPECT_EQ(paid_out, 39u);
  EXPECT_EQ(frames_out, 41u);
  EXPECT_EQ(first_out, "winch_test/joint_9_elevation");
  EXPECT_EQ(frame_out, "winch_test/link_9");
  EXPECT_EQ(moved, buffer) << "joint_12's name was copied, not moved";
  EXPECT_EQ(hauled_in, 18u);
  EXPECT_EQ(o.joints.name, at_start);
  EXPECT_EQ(o.joints.name.data(), names) << "the name vector was reallocated";
  EXPECT_EQ(o.joints.name[0].c_str(), buffer);
  EXPECT_EQ(o.transforms[1].child_frame_id, "winch_test/link_12");
  EXPECT_EQ(o.transforms[1].header.frame_id, "winch_test/cable_paper");
  EXPECT_EQ(o.transforms.back().child_frame_id, "winch_test/cable_load");
  EXPECT_EQ(o.markers.markers[0].points.size(), 11u);
  EXPECT_EQ(o.stowed_joint_names.size(), 33u);
}

/// Steps `sim` until its base link's slot is `first` (at most `seconds` of simulated time).
void stepUntilFirstLink(CableSimulator& sim, int first, double seconds) {
  const long steps = std::lround(seconds / sim.dt());
  for (long i = 0; i < steps && sim.firstLink() != first; ++i) ASSERT_TRUE(sim.step().ok);
  ASSERT_EQ(sim.firstLink(), first);
}

TEST(WinchOutputs, FilledFromASimulatorThatPaysOutAndHaulsIn) {
  const CableParams p = winchParams();
  const CableFrameNames names = prefixed();
  CableSimulator sim(p);
  CableOutputs o;
  prepareOutputs(p, names, "world", o);
  OutputSource source;
  source.spring_force = Eigen::VectorXd::Zero(3 * p.links);
  NodeStatus status;
  const auto publish = [&] {
    ASSERT_TRUE(readOutputs(sim, source));
    status.winch = winchStatus(source);
    g_allocations = 0;
    g_counting = true;
    shapeOutputs(source.snapshot.first_link, o);
    fillJointState(source, ros::Time(10.0), o.joints);
    fillTransforms(source, Eigen::Vector3d::Zero(), ros::Time(10.0), o.transforms);
    fillMarkers(source, p.totalLength(), 1000.0, ros::Time(10.0), o.markers);
    fillCableState(source, status, ros::Time(10.0), o.state);
    fillDiagnostics(status, ros::Time(10.0), o.diagnostics);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "a cycle's filling allocated";
    ASSERT_TRUE(allFinite(o));
    ASSERT_TRUE(allFinite(status));
  };
  const auto expectConsistent = [&] {
    const SimulationSnapshot& s = source.snapshot;
    const int first = sim.firstLink(), deployed = p.links - first;
    EXPECT_EQ(o.state.first_link, unsigned(first));
    EXPECT_EQ(o.state.deployed_links, unsigned(deployed));
    EXPECT_DOUBLE_EQ(o.state.deployed_length, sim.deployedLength());
    EXPECT_DOUBLE_EQ(o.state.winch_speed, sim.winch().motion().speed);
    EXPECT_DOUBLE_EQ(o.state.line_pull, s.chain.tension(first));
    EXPECT_DOUBLE_EQ(o.state.top_tension, o.state.line_pull);
    EXPECT_EQ(o.state.links_added, unsigned(sim.linksAdded()));
    EXPECT_EQ(o.state.links_removed, unsigned(sim.linksRemoved()));
    ASSERT_EQ(o.state.tension.size(), std::size_t(p.links));
    for (int k = 0; k < first; ++k) EXPECT_EQ(o.state.tension[k], 0.0) << "slot " << k << " on the drum";
    ASSERT_EQ(o.joints.name.size(), std::size_t(3 * deployed));
    for (int i = 0; i < 3 * deployed; ++i) {
      EXPECT_EQ(o.joints.name[i], names.joint(3 * first + i));
      EXPECT_EQ(o.joints.position[i], s.q(3 * first + i));
    }
    ASSERT_EQ(o.transforms.size(), std::size_t(2 + 3 * deployed));
    EXPECT_EQ(o.transforms[1].child_frame_id, names.link(first + 1));
    EXPECT_NEAR(o.transforms[1].transform.translation.z, 0.0, 1e-12) << "the base link's frame is at the base";
    EXPECT_EQ(o.transforms[4].child_frame_id, names.link(first + 2));
    EXPECT_DOUBLE_EQ(o.transforms[4].transform.translation.z, source.snapshot.link_frames[first + 1].position.z());
    const auto& line = o.markers.markers[0];
    ASSERT_EQ(line.points.size(), std::size_t(deployed + 1));
    EXPECT_DOUBLE_EQ(line.points.back().z, s.chain.ends(2, p.links));
    EXPECT_NEAR(line.points.front().z, 0.0, 1e-12);
    // The winch's diagnostics.
    const auto& values = o.diagnostics.status[0].values;
    ASSERT_EQ(values.size(), 23u);  // 13, the winch's 7, the limits' 3
    EXPECT_EQ(values[13].key, "deployed length [m]");
    EXPECT_NEAR(std::stod(values[13].value), sim.deployedLength(), 1e-5 * sim.deployedLength());
    EXPECT_EQ(std::stoi(values[14].value), deployed);
    EXPECT_EQ(values[16].key, "line pull [N]");
    EXPECT_EQ(values[17].key, "winch command");
  };
  publish();
  expectConsistent();
  EXPECT_EQ(o.diagnostics.status[0].values[17].value, "stop (speed 0)");
  // Pay out two links at 2 m/s.
  sim.commandWinchSpeed(2.0);
  stepUntilFirstLink(sim, 9, 10.0);
  publish();
  expectConsistent();
  EXPECT_EQ(o.diagnostics.status[0].values[17].value, "pay out at 2 m/s");
  EXPECT_GT(o.state.links_added, 1u);
  // Haul in to 12 m: links go back onto the drum.
  sim.commandWinchLength(12.0);
  stepUntilFirstLink(sim, 14, 20.0);
  publish();
  expectConsistent();
  EXPECT_EQ(o.diagnostics.status[0].values[17].value, "to length 12 m");
  EXPECT_GT(o.state.links_removed, 0u);
  // And a reset: back to the configured deployment.
  sim.reset();
  publish();
  expectConsistent();
  EXPECT_EQ(o.joints.name.front(), names.joint(33));
}

TEST(WinchOutputs, EveryNewFieldIsCheckedFinite) {
  CableOutputs o;
  prepareOutputs(winchParams(), prefixed(), "world", o);
  ASSERT_TRUE(allFinite(o));
  const auto expectCaught = [&](auto poison) {
    CableOutputs copy = o;
    poison(copy);
    EXPECT_FALSE(allFinite(copy));
  };
  expectCaught([](CableOutputs& c) { c.state.deployed_length = kNan; });
  expectCaught([](CableOutputs& c) { c.state.line_pull = kInf; });
  expectCaught([](CableOutputs& c) { c.state.winch_speed = -kInf; });
  NodeStatus s;
  ASSERT_TRUE(allFinite(s));
  for (double WinchStatus::*field : {&WinchStatus::deployed_length, &WinchStatus::speed, &WinchStatus::line_pull,
                                     &WinchStatus::commanded_speed, &WinchStatus::target_length}) {
    NodeStatus bad = s;
    bad.winch.*field = kNan;
    EXPECT_FALSE(allFinite(bad));
  }
}

TEST(AxialOutputs, CableStateAndDiagnosticsCarryTheStretches) {
  // A 20 kg mass on a 4-link line in air, its first link slack by 0.1 m: it falls and snaps the line taut.
  // cable_state carries each link's strain, the slack links, the largest tension and the snaps as the
  // simulator has them; /diagnostics names them; the filling allocates nothing.
  const CableParams p = loadConfigString(
      "cable: {links: 4, length: 4.0, diameter: 0.01, mass_per_length: 0.1, axial_stiffness: 1.0e5, "
      "stiffness: {model: bending}}\nload: {mass: 20.0}\nfluid: {density: 0.0}\n"
      "simulation: {integrator: rk4, dt: 0.0001}\n");
  CableSimulator sim(p);
  Eigen::VectorXd x = sim.state();
  x(StateLayout::stretch(p.links, false, 0)) = -0.1;
  sim.setState(x);
  CableOutputs o;
  prepareOutputs(p, prefixed(), "world", o);
  ASSERT_TRUE(o.state.axial);
  ASSERT_EQ(o.state.strain.size(), std::size_t(p.links));
  OutputSource source;
  source.spring_force = Eigen::VectorXd::Zero(3 * p.links);
  NodeStatus status;
  auto fill = [&] {
    ASSERT_TRUE(readOutputs(sim, source));
    status.slack_links = static_cast<unsigned>(source.snapshot.chain.slack_links);
    status.snaps = static_cast<unsigned>(source.snapshot.snaps);
    status.largest_tension = source.snapshot.largest_tension;
    g_allocations = 0;
    g_counting = true;
    fillCableState(source, status, ros::Time(1.0), o.state);
    fillDiagnostics(status, ros::Time(1.0), o.diagnostics);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "a cycle's filling allocated";
    ASSERT_TRUE(allFinite(o));
  };
  fill();
  EXPECT_EQ(o.state.slack_links, 1u);
  EXPECT_EQ(o.state.snaps, 0u);
  // 0.19 s: it has fallen 0.1 m (0.14 s), snapped the line taut and stretches it (k = 2.5e4 N/m, the
  // half period 0.09 s); the light links beyond the first ring about their unstretched length.
  for (int i = 0; i < 1900; ++i) ASSERT_TRUE(sim.step().ok);
  fill();
  EXPECT_GE(o.state.snaps, 1u);
  EXPECT_EQ(o.state.snaps, unsigned(sim.snaps()));
  EXPECT_EQ(o.state.slack_links, unsigned(source.snapshot.chain.slack_links));
  EXPECT_DOUBLE_EQ(o.state.max_tension, sim.largestTension());
  EXPECT_GT(o.state.max_tension, 20.0 * 9.81);  // a snap pulls harder than the weight
  for (int k = 0; k < p.links; ++k) EXPECT_DOUBLE_EQ(o.state.strain[k], source.snapshot.chain.strain(k));
  // Each link's TF frame sits at its base end as the dynamics have it, stretches included (the line is
  // stretched by millimetres here; summed rounding 1e-15 m).
  for (int k = 0; k < p.links; ++k) {
    EXPECT_LT((source.snapshot.link_frames[k].position - source.snapshot.chain.ends.col(k)).norm(), 1e-12) << "link " << k;
  }
  std::map<std::string, std::string> values;
  for (const auto& kv : o.diagnostics.status[0].values) values[kv.key] = kv.value;
  EXPECT_EQ(values["snaps"], std::to_string(sim.snaps()));
  EXPECT_EQ(values["slack links"], std::to_string(source.snapshot.chain.slack_links));
  EXPECT_NEAR(std::stod(values["largest tension [N]"]), sim.largestTension(), 1e-5 * sim.largestTension());
}

}  // namespace
}  // namespace cable_dynamics
