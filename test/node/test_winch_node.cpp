// The node's winch over ROS (test/winch.test, config test/node/winch_test.yaml): paying out on winch/speed,
// hauling in with winch/set_length, the outputs following the changing number of links, the guards; and a
// node without a winch (namespace no_winch) refusing both. Every wait is bounded. The tests share one node,
// but none depends on what another left: each starts from the configured deployment (SetUp: `reset`, the
// winch stopped at 20 m), so they pass alone (--gtest_filter) and in any order (--gtest_shuffle). Rates are measured against the published sim_time, not wall time, so that a loaded
// machine (lag) changes nothing but the wall time the test takes.
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <cable_msgs/GetModel.h>
#include <cable_msgs/Reset.h>
#include <cable_msgs/ResetToEquilibrium.h>
#include <cable_msgs/SetWinchLength.h>
#include <gtest/gtest.h>
#include <std_msgs/Float64.h>

#include "output_recorder.h"

namespace {

using cable_test::spinFor;
using cable_test::waitFor;

// test/node/winch_test.yaml
constexpr int kSlots = 21;            // 10 deployed + 11 on the drum (40 m in 2 m links, one more for the band)
constexpr int kFirstAtStart = 11;     // slot of the base link at start: links link_12 .. link_21
constexpr double kLength = 20.0;      // [m] deployed at start
constexpr double kMinLength = 6.0, kMaxLength = 40.0, kMaxSpeed = 2.0, kMaxAcceleration = 1.0;
constexpr double kGravity = 9.81, kRho = 1025.0, kDiameter = 0.03;
const double kCableSubmerged = 1.5 - kRho * M_PI * 0.25 * kDiameter * kDiameter;  // [kg/m]
constexpr double kLoadSubmerged = 40.0 - kRho * 0.01;                             // [kg]
constexpr double kLoadDragArea = 0.1, kSkinFriction = 0.01;                       // C_d A [m^2], C_t [-]
const std::string kNs = "/winch_test", kPrefix = "winch_test/";
/// Relative tolerance of the line pull against quasiStaticPull() once the speed is constant. The cable
/// hangs straight in still water, so the balance is exact but for rounding (measured: 1e-15): 0.1 %
/// leaves room for a cable that is not exactly vertical (a link change, the base link's changing length)
/// while any missing term shows: the drag (3.4 % of the pull at 0.5 m/s, 22 m; 100 % at 2 m/s, 30 m), its
/// skin-friction part alone (0.6 % and 22 %), the load's buoyancy (23 % at rest).
constexpr double kPullTolerance = 1e-3;

/// The line pull of a straight hanging cable paid out (v > 0) or hauled in (v < 0) at a constant speed:
/// the submerged weight below the winch less the drag that opposes the motion (the load's, and the skin
/// friction along the cable, 1/2 rho C_t pi d L v |v|) [N].
double quasiStaticPull(double length, double speed) {
  const double drag = 0.5 * kRho * (kLoadDragArea + kSkinFriction * M_PI * kDiameter * length) * speed * std::abs(speed);
  return kGravity * (kCableSubmerged * length + kLoadSubmerged) - drag;
}

/// What the test keeps of the winch node's outputs besides the recorder's latest messages.
struct History {
  std::vector<cable_msgs::CableState> states;  ///< every cable_state since the last clear()
  std::vector<std::string> tf_frames;          ///< child frames of the node's last /tf message
  std::map<std::string, geometry_msgs::Vector3> first_seen;  ///< where each link frame was when it first appeared
  bool inconsistent = false;                   ///< a message whose shape did not match its cable_state
  std::string why;
};

History* history = nullptr;

void onState(const cable_msgs::CableState& m) {
  if (m.deployed_links + m.first_link != m.tension.size() && !history->inconsistent) {
    history->inconsistent = true;
    history->why = "cable_state: deployed_links + first_link != tension.size()";
  }
  history->states.push_back(m);
}

void onTf(const tf2_msgs::TFMessage& m) {
  if (m.transforms.empty() || m.transforms[0].child_frame_id != kPrefix + "cable_paper") return;  // not our node's
  history->tf_frames.clear();
  for (const auto& t : m.transforms) {
    history->tf_frames.push_back(t.child_frame_id);
    if (!history->first_seen.count(t.child_frame_id)) history->first_seen[t.child_frame_id] = t.transform.translation;
  }
}

std::string jointName(int k, const char* kind) { return kPrefix + "joint_" + std::to_string(k) + "_" + kind; }

class WinchNodeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    history = new History;
    nh = new ros::NodeHandle;
    recorder = new cable_test::OutputRecorder(*nh, kNs, "cable_dynamics: " + kPrefix);
    subs = new std::vector<ros::Subscriber>{nh->subscribe(kNs + "/cable_state", 1000, onState),
                                            nh->subscribe("/tf", 1000, onTf)};
    speed = new ros::Publisher(nh->advertise<std_msgs::Float64>(kNs + "/winch/speed", 100));
    ASSERT_TRUE(waitFor([] { return recorder->allReceived() && speed->getNumSubscribers() > 0; }, 30.0))
        << "the winch node published nothing within 30 s";
  }

  /// The configured start, whatever the test before did: `reset` puts the winch back at its configured
  /// deployment (20 m) and speed (0) and the counters at zero; the history starts again with it.
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(kNs + "/reset", ros::Duration(10.0)));
    cable_msgs::Reset reset;
    const long states_before = recorder->state_count, joints_before = recorder->joint_count;
    ASSERT_TRUE(ros::service::call(kNs + "/reset", reset));
    ASSERT_TRUE(reset.response.success) << reset.response.message;
    ASSERT_TRUE(waitFor([&] {
      if (recorder->state_count <= states_before + 2 || recorder->joint_count <= joints_before + 2) return false;
      const cable_msgs::CableState& s = state();
      return s.sim_time < 0.5 && s.first_link == unsigned(kFirstAtStart) && s.winch_speed == 0.0 &&
             s.links_added == 0u && s.links_removed == 0u && std::abs(s.deployed_length - kLength) < 1e-9 &&
             recorder->joints.name.size() == 3u * (kSlots - kFirstAtStart);
    }, 10.0)) << "the reset did not restore the configured deployment";
    history->states.clear();
    history->first_seen.clear();
    history->inconsistent = false;
    history->why.clear();
  }

  /// Winch to `length` [m] with winch/set_length, and stopped there.
  static void moveTo(double length) {
    cable_msgs::SetWinchLength srv;
    srv.request.length = length;
    ASSERT_TRUE(ros::service::waitForService(kNs + "/winch/set_length", ros::Duration(10.0)));
    ASSERT_TRUE(ros::service::call(kNs + "/winch/set_length", srv));
    ASSERT_TRUE(srv.response.success) << srv.response.message;
    ASSERT_TRUE(waitFor([&] { return std::abs(state().deployed_length - length) < 1e-3 && state().winch_speed == 0.0; }, 60.0))
        << "deployed " << state().deployed_length << " m, speed " << state().winch_speed << " m/s after 60 s";
  }

  /// Publishes `v` [m/s] on winch/speed every 20 ms until `done` or `seconds` of wall time.
  static bool commandUntil(double v, const std::function<bool()>& done, double seconds) {
    std_msgs::Float64 m;
    m.data = v;
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      speed->publish(m);
      spinFor(0.02);
      if (done()) return true;
    }
    return done();
  }
  /// Publishes `v` on winch/speed once.
  static void sendOnce(double v) {
    std_msgs::Float64 m;
    m.data = v;
    speed->publish(m);
  }
  static const cable_msgs::CableState& state() { return recorder->state; }

  static ros::NodeHandle* nh;
  static cable_test::OutputRecorder* recorder;
  static std::vector<ros::Subscriber>* subs;
  static ros::Publisher* speed;
};

ros::NodeHandle* WinchNodeTest::nh = nullptr;
cable_test::OutputRecorder* WinchNodeTest::recorder = nullptr;
std::vector<ros::Subscriber>* WinchNodeTest::subs = nullptr;
ros::Publisher* WinchNodeTest::speed = nullptr;

TEST_F(WinchNodeTest, StartsAsConfiguredWithOnlyTheDeployedLinksPublished) {
  ASSERT_TRUE(waitFor([] { return !history->tf_frames.empty(); }, 10.0));
  const cable_msgs::CableState& s = state();
  EXPECT_NEAR(s.deployed_length, kLength, 1e-9);
  EXPECT_EQ(s.first_link, unsigned(kFirstAtStart));
  EXPECT_EQ(s.deployed_links, unsigned(kSlots - kFirstAtStart));
  EXPECT_EQ(s.links_added, 0u);
  EXPECT_EQ(s.links_removed, 0u);
  EXPECT_EQ(s.winch_speed, 0.0);
  // tension[]: one entry per slot, 0 on the drum; top_tension is the line pull.
  ASSERT_EQ(s.tension.size(), std::size_t(kSlots));
  for (int k = 0; k < kFirstAtStart; ++k) EXPECT_EQ(s.tension[k], 0.0) << k;
  EXPECT_DOUBLE_EQ(s.top_tension, s.line_pull);
  EXPECT_DOUBLE_EQ(s.line_pull, s.tension[kFirstAtStart]);
  // At rest, hanging straight: the submerged weight of 20 m and the load (444.0 N), to 0.1 %.
  EXPECT_NEAR(s.line_pull / quasiStaticPull(kLength, 0.0), 1.0, 1e-3) << s.line_pull;
  // The joint states, the frames and the line of the deployed links only, named by their slots.
  const auto& j = recorder->joints;
  ASSERT_EQ(j.name.size(), 3u * (kSlots - kFirstAtStart));
  EXPECT_EQ(j.position.size(), j.name.size());
  EXPECT_EQ(j.effort.size(), j.name.size());
  EXPECT_EQ(j.name.front(), jointName(kFirstAtStart + 1, "elevation"));
  EXPECT_EQ(j.name.back(), jointName(kSlots, "torsion"));
  EXPECT_EQ(history->tf_frames.size(), 2u + 3u * (kSlots - kFirstAtStart));
  const std::set<std::string> frames(history->tf_frames.begin(), history->tf_frames.end());
  EXPECT_TRUE(frames.count(kPrefix + "link_12"));
  EXPECT_TRUE(frames.count(kPrefix + "link_21_elevation"));
  EXPECT_TRUE(frames.count(kPrefix + "cable_load"));
  EXPECT_FALSE(frames.count(kPrefix + "link_11")) << "a link on the drum has a frame";
  EXPECT_EQ(recorder->markers.markers.at(0).points.size(), std::size_t(kSlots - kFirstAtStart + 1));
  // The URDF describes every slot (the longest deployment) at its configured length.
  std::string urdf;
  ASSERT_TRUE(ros::param::get(kNs + "/robot_description", urdf));
  EXPECT_NE(urdf.find("\"" + jointName(1, "elevation") + "\""), std::string::npos);
  EXPECT_NE(urdf.find("\"" + kPrefix + "link_21\""), std::string::npos);
  EXPECT_EQ(urdf.find("mass value=\"0\""), std::string::npos) << "a massless slot in the URDF";
}

// Paying out at 0.5 m/s: the deployed length grows at the commanded speed, links are added at the winch, the
// joints that existed keep their names, and the line pull is the quasi-static one.
TEST_F(WinchNodeTest, PaysOutAtTheCommandedSpeed) {
  const std::vector<std::string> names_before = recorder->joints.name;
  const unsigned links_before = state().deployed_links;
  history->states.clear();
  const double v = 0.5;
  ASSERT_TRUE(commandUntil(v, [] { return state().deployed_length > 23.5; }, 60.0))
      << "deployed " << state().deployed_length << " m after 60 s";
  // Samples at the commanded speed (after the 0.5 s ramp at 1 m/s^2).
  std::vector<cable_msgs::CableState> steady;
  double reached_at = -1.0;
  for (const auto& s : history->states) {
    if (std::abs(s.winch_speed - v) > 1e-9) continue;
    if (reached_at < 0.0) reached_at = s.sim_time;
    steady.push_back(s);
  }
  ASSERT_GE(steady.size(), 50u) << "too few samples at the commanded speed";
  // The deployed length is the winch's integral of its speed, exact up to rounding: the slope over the
  // published sim_time is the commanded speed to 1e-6 m/s (wall time does not enter).
  const auto& a = steady.front();
  const auto& b = steady.back();
  ASSERT_GT(b.sim_time - a.sim_time, 2.0);
  EXPECT_NEAR((b.deployed_length - a.deployed_length) / (b.sim_time - a.sim_time), v, 1e-6);
  // Line pull: for a straight inextensible cable hanging in still water at a constant speed the
  // quasi-static balance is exact (measured: 1e-15 relative); see kPullTolerance.
  double worst = 0.0;
  for (const auto& s : steady) {
    if (s.sim_time < reached_at + 0.2) continue;
    EXPECT_GT(s.line_pull, 0.0);
    worst = std::max(worst, std::abs(s.line_pull / quasiStaticPull(s.deployed_length, v) - 1.0));
  }
  EXPECT_LT(worst, kPullTolerance) << "line pull off the quasi-static one by " << 100.0 * worst << " %";
  std::cout << "paying out at 0.5 m/s: line pull within " << 100.0 * worst << " % of the quasi-static one over "
            << steady.size() << " samples" << std::endl;
  // More links, more joints; the joints that existed keep their names (they are the last ones).
  ASSERT_TRUE(waitFor([&] { return recorder->joints.name.size() == 3u * state().deployed_links; }, 5.0));
  EXPECT_GT(state().deployed_links, links_before);
  EXPECT_GT(state().links_added, 0u);
  EXPECT_EQ(state().first_link + state().deployed_links, unsigned(kSlots));
  const auto& names = recorder->joints.name;
  ASSERT_GT(names.size(), names_before.size());
  for (std::size_t i = 0; i < names_before.size(); ++i) {
    EXPECT_EQ(names[names.size() - names_before.size() + i], names_before[i]) << i;
  }
  EXPECT_EQ(names.front(), jointName(state().first_link + 1, "elevation"));
  // The new base link's frame appeared at the base (the paper frame's origin).
  const std::string added = kPrefix + "link_" + std::to_string(kFirstAtStart);
  ASSERT_TRUE(history->first_seen.count(added)) << added << " never appeared on /tf";
  const auto& p = history->first_seen[added];
  EXPECT_LT(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1e-6);
  EXPECT_FALSE(history->inconsistent) << history->why;
}

// At max_speed every number published is finite; a faster command is rejected (not clamped) and counted.
TEST_F(WinchNodeTest, PaysOutAtMaxSpeedWithEveryNumberFinite) {
  const long checked_before = recorder->numbers_checked;
  ASSERT_TRUE(commandUntil(kMaxSpeed, [] { return state().deployed_length > 33.0; }, 60.0))
      << "deployed " << state().deployed_length << " m after 60 s";
  EXPECT_NEAR(state().winch_speed, kMaxSpeed, 1e-9);
  const unsigned rejected = state().rejected_inputs;
  sendOnce(1.01 * kMaxSpeed);
  ASSERT_TRUE(waitFor([&] { return state().rejected_inputs == rejected + 1; }, 5.0)) << "2.02 m/s was not rejected";
  EXPECT_NEAR(state().winch_speed, kMaxSpeed, 1e-9) << "a rejected command changed the speed";
  // Stop short of max_length.
  ASSERT_TRUE(commandUntil(0.0, [] { return std::abs(state().winch_speed) < 1e-9; }, 20.0));
  EXPECT_LT(state().deployed_length, kMaxLength);
  // At 2 m/s the drag takes a large share of the weight (263 N of the 520 N submerged weight at 30 m): the line pull still
  // follows the quasi-static balance.
  double fastest = 0.0, reached_at = -1.0, worst = 0.0;
  int steady = 0;
  for (const auto& s : history->states) {
    fastest = std::max(fastest, s.winch_speed);
    for (double x : {s.deployed_length, s.line_pull, s.winch_speed}) EXPECT_TRUE(std::isfinite(x));
    if (s.winch_speed != kMaxSpeed) continue;
    if (reached_at < 0.0) reached_at = s.sim_time;
    if (s.sim_time < reached_at + 0.2) continue;
    EXPECT_GT(s.line_pull, 0.0);
    worst = std::max(worst, std::abs(s.line_pull / quasiStaticPull(s.deployed_length, kMaxSpeed) - 1.0));
    ++steady;
  }
  EXPECT_LE(fastest, kMaxSpeed);
  EXPECT_GT(steady, 100);
  EXPECT_LT(worst, kPullTolerance) << "line pull off the quasi-static one by " << 100.0 * worst << " %";
  std::cout << "paying out at 2 m/s: line pull within " << 100.0 * worst << " % of the quasi-static one over "
            << steady << " samples" << std::endl;
  EXPECT_TRUE(recorder->non_finite.empty()) << "non-finite number in " << recorder->non_finite;
  std::cout << "numbers checked in this test: " << recorder->numbers_checked - checked_before << std::endl;
  EXPECT_GT(recorder->numbers_checked - checked_before, 100000);
  EXPECT_EQ(state().diverged_steps, 0u);
  // The shapes follow the deployment.
  ASSERT_TRUE(waitFor([] { return recorder->joints.name.size() == 3u * state().deployed_links; }, 5.0));
  EXPECT_EQ(recorder->markers.markers.at(0).points.size(), state().deployed_links + 1u);
  EXPECT_EQ(history->tf_frames.size(), 2u + 3u * state().deployed_links);
  EXPECT_FALSE(history->inconsistent) << history->why;
}

// set_length to a shorter length: the winch hauls in, stops there, links go back onto the drum and their
// joints and frames stop.
TEST_F(WinchNodeTest, SetLengthHaulsInToIt) {
  moveTo(31.0);  // paid out beyond the target first
  if (HasFatalFailure()) return;
  const unsigned links_before = state().deployed_links;
  cable_msgs::SetWinchLength srv;
  srv.request.length = 25.0;
  ASSERT_TRUE(ros::service::waitForService(kNs + "/winch/set_length", ros::Duration(10.0)));
  ASSERT_TRUE(ros::service::call(kNs + "/winch/set_length", srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_GT(srv.response.deployed_length, 30.0);
  EXPECT_NE(srv.response.message.find("25"), std::string::npos) << srv.response.message;
  // At the target the winch stops: its speed is exactly 0 (the core's stopping law, test_winch).
  ASSERT_TRUE(waitFor([] { return std::abs(state().deployed_length - 25.0) < 1e-3 && state().winch_speed == 0.0; }, 60.0))
      << "deployed " << state().deployed_length << " m, speed " << state().winch_speed << " m/s after 60 s";
  spinFor(0.5);
  EXPECT_NEAR(state().deployed_length, 25.0, 1e-3);
  EXPECT_LT(state().deployed_links, links_before);
  EXPECT_GT(state().links_removed, 0u);
  ASSERT_TRUE(waitFor([] { return recorder->joints.name.size() == 3u * state().deployed_links; }, 5.0));
  EXPECT_EQ(recorder->joints.name.front(), jointName(state().first_link + 1, "elevation"));
  EXPECT_EQ(recorder->markers.markers.at(0).points.size(), state().deployed_links + 1u);
  ASSERT_TRUE(waitFor([] { return history->tf_frames.size() == 2u + 3u * state().deployed_links; }, 5.0));
  const std::set<std::string> frames(history->tf_frames.begin(), history->tf_frames.end());
  EXPECT_FALSE(frames.count(kPrefix + "link_" + std::to_string(state().first_link))) << "a hauled-in link has a frame";
  // At rest at 25 m: the static line pull.
  spinFor(1.0);
  EXPECT_NEAR(state().line_pull / quasiStaticPull(25.0, 0.0), 1.0, 0.01) << state().line_pull;
  EXPECT_TRUE(recorder->non_finite.empty()) << recorder->non_finite;
}

TEST_F(WinchNodeTest, ResetToEquilibriumPutsTheCableAtRest) {
  // Paid out to 25 m the cable still swings a little; the service puts it at rest in its static shape
  // at the present deployed length (straight down in still water): no joint moves afterwards, and the
  // line pull is the static one.
  moveTo(25.0);
  if (HasFatalFailure()) return;
  cable_msgs::ResetToEquilibrium srv;
  ASSERT_TRUE(ros::service::waitForService(kNs + "/reset_to_equilibrium", ros::Duration(10.0)));
  const double length = state().deployed_length;
  ASSERT_TRUE(ros::service::call(kNs + "/reset_to_equilibrium", srv));
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_LT(srv.response.residual, 1e-9);
  EXPECT_NEAR(srv.response.line_pull / quasiStaticPull(length, 0.0), 1.0, 1e-9);
  spinFor(0.5);
  const double since = state().sim_time;
  double fastest = 0.0;
  for (int i = 0; i < 50; ++i) {
    spinFor(0.02);
    for (double v : recorder->joints.velocity) fastest = std::max(fastest, std::abs(v));
  }
  EXPECT_GT(state().sim_time, since + 0.2) << "the node stopped stepping";
  EXPECT_LT(fastest, 1e-9) << "a joint moves after the reset to equilibrium [rad/s]";
  EXPECT_NEAR(state().line_pull / quasiStaticPull(length, 0.0), 1.0, 1e-6);
  EXPECT_TRUE(recorder->non_finite.empty()) << recorder->non_finite;
}

TEST_F(WinchNodeTest, OutOfRangeLengthsAreRefusedNamingTheRange) {
  const double before = state().deployed_length;
  for (double length : {50.0, 3.0, std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    cable_msgs::SetWinchLength srv;
    srv.request.length = length;
    ASSERT_TRUE(ros::service::call(kNs + "/winch/set_length", srv));
    EXPECT_FALSE(srv.response.success) << length;
    EXPECT_NE(srv.response.message.find("[6, 40] m"), std::string::npos) << srv.response.message;
  }
  spinFor(1.0);
  EXPECT_NEAR(state().deployed_length, before, 1e-6) << "a refused length moved the winch";
}

TEST_F(WinchNodeTest, NanSpeedIsRejectedAndCounted) {
  const double before = state().deployed_length;
  const unsigned rejected = state().rejected_inputs, received = state().received_inputs;
  sendOnce(std::numeric_limits<double>::quiet_NaN());
  ASSERT_TRUE(waitFor([&] { return state().rejected_inputs == rejected + 1; }, 5.0));
  EXPECT_EQ(state().received_inputs, received + 1);
  sendOnce(std::numeric_limits<double>::infinity());
  ASSERT_TRUE(waitFor([&] { return state().rejected_inputs == rejected + 2; }, 5.0));
  spinFor(0.5);
  EXPECT_LT(std::abs(state().winch_speed), 1e-4) << "a rejected command moved the winch";
  EXPECT_NEAR(state().deployed_length, before, 1e-3);
  EXPECT_TRUE(recorder->non_finite.empty()) << recorder->non_finite;
}

TEST_F(WinchNodeTest, DiagnosticsReportTheWinch) {
  moveTo(25.0);
  if (HasFatalFailure()) return;
  ASSERT_TRUE(waitFor([] { return recorder->diagnostics_count > 0; }, 5.0));
  const long seen = recorder->diagnostics_count;
  ASSERT_TRUE(waitFor([&] { return recorder->diagnostics_count > seen; }, 5.0));
  std::map<std::string, std::string> values;
  for (const auto& kv : recorder->diagnostics.values) values[kv.key] = kv.value;
  ASSERT_TRUE(values.count("deployed length [m]"));
  EXPECT_NEAR(std::stod(values["deployed length [m]"]), 25.0, 1e-3);
  EXPECT_EQ(std::stoi(values["deployed links"]), int(state().deployed_links));
  EXPECT_NEAR(std::stod(values["winch speed [m/s]"]), 0.0, 1e-4);
  EXPECT_NEAR(std::stod(values["line pull [N]"]), state().line_pull, 0.01 * state().line_pull);
  EXPECT_EQ(values["winch command"], "to length 25 m");
  EXPECT_TRUE(values.count("links added") && values.count("links removed"));
}

TEST_F(WinchNodeTest, GetModelStaysFiniteWithTheDrumsSlots) {
  cable_msgs::GetModel model;
  ASSERT_TRUE(ros::service::call(kNs + "/get_model", model));
  ASSERT_EQ(model.response.q.size(), 3u * kSlots);
  for (double x : model.response.M) ASSERT_TRUE(std::isfinite(x));
  for (double x : model.response.G) ASSERT_TRUE(std::isfinite(x));
}

// reset with a shape: the winch goes back to its configured deployment, the deployed links take the shape;
// a drum slot given a value is refused, naming it.
TEST_F(WinchNodeTest, ResetWithAShapeRestoresTheConfiguredDeployment) {
  cable_msgs::Reset bad;
  bad.request.positions.assign(3 * kSlots, 0.0);
  bad.request.positions[3] = 0.2;  // slot 2 (joint_2_elevation), on the drum
  ASSERT_TRUE(ros::service::call(kNs + "/reset", bad));
  EXPECT_FALSE(bad.response.success);
  EXPECT_NE(bad.response.message.find("joint_2_elevation"), std::string::npos) << bad.response.message;
  EXPECT_NE(bad.response.message.find("drum"), std::string::npos) << bad.response.message;
  cable_msgs::Reset reset;
  reset.request.positions.assign(3 * kSlots, 0.0);
  for (int k = kFirstAtStart; k < kSlots; ++k) reset.request.positions[3 * k] = 0.1;
  const long states_before = recorder->state_count, joints_before = recorder->joint_count;
  ASSERT_TRUE(ros::service::call(kNs + "/reset", reset));
  EXPECT_TRUE(reset.response.success) << reset.response.message;
  // Outputs of the run the reset started (SetUp's reset already left the configured deployment: the
  // counts tell the new messages from the old).
  ASSERT_TRUE(waitFor([&] {
    return recorder->state_count > states_before + 2 && recorder->joint_count > joints_before + 2 &&
           state().sim_time < 0.5 && state().first_link == unsigned(kFirstAtStart);
  }, 5.0));
  EXPECT_NEAR(state().deployed_length, kLength, 1e-9);
  EXPECT_EQ(state().links_added, 0u);
  ASSERT_TRUE(waitFor([] { return recorder->joints.name.size() == 3u * (kSlots - kFirstAtStart); }, 5.0));
  EXPECT_EQ(recorder->joints.name.front(), jointName(kFirstAtStart + 1, "elevation"));
  EXPECT_NEAR(recorder->joints.position.front(), 0.1, 0.05) << "the deployed links did not take the shape";
  EXPECT_TRUE(recorder->non_finite.empty()) << recorder->non_finite;
}

// Without a winch the topic's messages are rejected and counted, the service says there is none, and
// cable_state reports the fixed cable.
TEST_F(WinchNodeTest, ANodeWithoutAWinchRefusesItsCommands) {
  cable_test::OutputRecorder plain(*nh, "/no_winch", "cable_dynamics: no_winch/");
  ASSERT_TRUE(waitFor([&] { return plain.allReceived(); }, 20.0));
  const cable_msgs::CableState& s = plain.state;
  EXPECT_NEAR(s.deployed_length, 12.0, 1e-9);  // test/node/node_test.yaml
  EXPECT_EQ(s.first_link, 0u);
  EXPECT_EQ(s.deployed_links, 6u);
  EXPECT_EQ(s.winch_speed, 0.0);
  EXPECT_DOUBLE_EQ(s.line_pull, s.top_tension);
  EXPECT_DOUBLE_EQ(s.line_pull, s.tension.at(0));
  EXPECT_EQ(plain.joints.name.size(), 18u);
  ros::Publisher other = nh->advertise<std_msgs::Float64>("/no_winch/winch/speed", 10);
  ASSERT_TRUE(waitFor([&] { return other.getNumSubscribers() > 0; }, 10.0));
  const unsigned rejected = plain.state.rejected_inputs;
  std_msgs::Float64 m;
  m.data = 0.5;
  other.publish(m);
  ASSERT_TRUE(waitFor([&] { return plain.state.rejected_inputs == rejected + 1; }, 5.0));
  EXPECT_NEAR(plain.state.deployed_length, 12.0, 1e-9);
  cable_msgs::SetWinchLength srv;
  srv.request.length = 10.0;
  ASSERT_TRUE(ros::service::call("/no_winch/winch/set_length", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_NE(srv.response.message.find("no winch"), std::string::npos) << srv.response.message;
  EXPECT_NEAR(srv.response.deployed_length, 12.0, 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_winch_node");
  return RUN_ALL_TESTS();
}
