// The node's limits parts without a roscore (cable.limits; docs/NODE.md): cable_state carries each joint's
// bend radius and each link's utilisation, finite (a straight joint's infinite radius as 1e9 m), equal to
// the simulator's; /diagnostics is OK within the limits and WARN while one is exceeded, naming the limit
// and the link, with the cycles in excess counted; the rviz tube coloured by utilisation (ros.markers.
// colour_by), red at the limit; and the option's refusal. The filling allocates nothing.
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <new>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/ros/finite_messages.h"
#include "cable_dynamics/ros/message_builders.h"
#include "cable_dynamics/ros/node_options.h"

// Counts heap allocations while g_counting is set (this test binary only).
#include "../allocation_counter.h"

namespace cable_dynamics {
namespace {

/// A hanging cable (10 links, 20 m, straight down at rest: every joint straight) whose top tension is the
/// submerged weight g (w L + m_sub) = 444.0 N, with a safe working load of `swl` [N].
CableParams hanging(double swl) {
  std::ostringstream value;
  value << std::setprecision(17) << swl;
  return loadConfigString("cable: {links: 10, length: 20.0, diameter: 0.03, mass_per_length: 1.5, limits: "
                          "{max_tension: " + value.str() + ", min_bend_radius: 3.0}}\n"
                          "load: {mass: 40.0, volume: 0.01}\nfluid: {density: 1025.0}\n");
}

struct Node {
  explicit Node(const CableParams& p) : sim(p) {
    CableFrameNames names;
    names.prefix = "limits_test/";
    prepareOutputs(p, names, "world", outputs);
    source.spring_force = Eigen::VectorXd::Zero(3 * p.links);
  }
  /// One published cycle as CableNode::publishOutputs has it, allocations counted.
  void cycle(MarkerColour colour) {
    ASSERT_TRUE(readOutputs(sim, source));
    g_allocations = 0;
    g_counting = true;
    updateLimitStatus(source.snapshot, status.limits);
    fillCableState(source, status, ros::Time(1.0), outputs.state);
    fillMarkers(source, 20.0, 1000.0, ros::Time(1.0), outputs.markers, colour);
    fillDiagnostics(status, ros::Time(1.0), outputs.diagnostics);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "a cycle's filling allocated";
  }
  std::map<std::string, std::string> diagnostics() const {
    std::map<std::string, std::string> values;
    for (const auto& kv : outputs.diagnostics.status[0].values) values[kv.key] = kv.value;
    return values;
  }
  CableSimulator sim;
  CableOutputs outputs;
  OutputSource source;
  NodeStatus status;
};

const double kTopTension = 9.81 * ((1.5 - 1025.0 * M_PI * 0.015 * 0.015) * 20.0 + 40.0 - 10.25);  // [N]

TEST(LimitOutputs, CableStateCarriesFiniteBendRadiiAndUtilisation) {
  Node node(hanging(2.0 * kTopTension));
  node.cycle(MarkerColour::kTension);
  const cable_msgs::CableState& m = node.outputs.state;
  ASSERT_EQ(m.bend_radius.size(), 10u);
  ASSERT_EQ(m.utilisation.size(), 10u);
  EXPECT_TRUE(allFinite(m));
  EXPECT_TRUE(allFinite(node.outputs));
  const LimitReport& r = node.source.snapshot.chain.limits;
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(r.bend_radius(k), std::numeric_limits<double>::infinity()) << k;  // straight
    EXPECT_EQ(m.bend_radius[k], kPublishedStraightRadius) << k;
    EXPECT_EQ(m.utilisation[k], r.utilisation(k)) << k;
  }
  EXPECT_EQ(m.min_bend_radius, kPublishedStraightRadius);
  EXPECT_NEAR(m.max_utilisation, 0.5, 1e-12);  // the top link: T / (2 T)
  EXPECT_EQ(m.max_utilisation, r.max_utilisation);
  // Within the limits: OK, nothing counted.
  EXPECT_EQ(node.outputs.diagnostics.status[0].level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(node.diagnostics()["cycles over a limit"], "0");
  EXPECT_EQ(node.diagnostics()["max utilisation"], "0.5");
  EXPECT_EQ(node.diagnostics()["min bend radius [m]"], "1e+09");
}

TEST(LimitOutputs, DiagnosticsWarnWhileATensionLimitIsExceededAndCountTheCycles) {
  // A safe working load of 0.8 T: the top link is at 1.25, the tension limit exceeded on link 1 (slot 0).
  Node node(hanging(0.8 * kTopTension));
  for (int i = 1; i <= 3; ++i) {
    node.cycle(MarkerColour::kTension);
    ASSERT_TRUE(node.sim.step().ok);
    const diagnostic_msgs::DiagnosticStatus& d = node.outputs.diagnostics.status[0];
    EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::WARN);
    EXPECT_NE(d.message.find("tension on link 1 (utilisation 1.25)"), std::string::npos) << d.message;
    EXPECT_EQ(d.message.find("bend"), std::string::npos) << d.message;  // straight: the bend limit holds
    EXPECT_EQ(node.diagnostics()["cycles over a limit"], std::to_string(i));
    EXPECT_EQ(node.status.limits.cycles_in_excess, unsigned(i));
  }
  EXPECT_NEAR(node.outputs.state.max_utilisation, 1.25, 1e-9);
  EXPECT_TRUE(allFinite(node.status));
}

TEST(LimitOutputs, TubeColouredByUtilisationIsRedAtTheLimit) {
  // Coloured by utilisation the top link (1.25) is red and one at 0.5 green; by tension (the scale's top
  // at 1000 N) the colours are tension's.
  Node node(hanging(0.8 * kTopTension));
  node.cycle(MarkerColour::kUtilisation);
  const visualization_msgs::MarkerArray& markers = node.outputs.markers;
  const visualization_msgs::Marker* tube = nullptr;
  for (const auto& m : markers.markers) {
    if (m.ns == "cable_tube" && m.id == 0) tube = &m;
  }
  ASSERT_NE(tube, nullptr);
  EXPECT_FLOAT_EQ(tube->color.r, 1.0f);
  EXPECT_FLOAT_EQ(tube->color.g, 0.0f);
  const std_msgs::ColorRGBA half = utilisationColor(0.5);
  EXPECT_FLOAT_EQ(half.g, 1.0f);
  EXPECT_FLOAT_EQ(half.r, 0.0f);
  bool labelled = false;
  for (const auto& m : markers.markers) labelled = labelled || m.text.find("utilisation: blue 0") != std::string::npos;
  EXPECT_TRUE(labelled);
  node.cycle(MarkerColour::kTension);
  EXPECT_FLOAT_EQ(tube->color.r, tensionColor(node.source.snapshot.chain.tension(0), 1000.0).r);
}

TEST(LimitOutputs, ColourByIsValidated) {
  EXPECT_EQ(parseNodeOptions(YAML::Load("{}"), "").colour_by, MarkerColour::kTension);  // the default
  EXPECT_EQ(parseNodeOptions(YAML::Load("{markers: {colour_by: utilisation}}"), "").colour_by, MarkerColour::kUtilisation);
  try {
    parseNodeOptions(YAML::Load("{markers: {colour_by: strain}}"), "");
    ADD_FAILURE() << "accepted colour_by: strain";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "ros.markers.colour_by");
    EXPECT_NE(std::string(e.what()).find("strain"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("utilisation"), std::string::npos) << e.what();
  }
  try {
    parseNodeOptions(YAML::Load("{markers: {color_by: tension}}"), "");
    ADD_FAILURE() << "accepted an unknown key";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "ros.markers.color_by");
  }
}

}  // namespace
}  // namespace cable_dynamics
