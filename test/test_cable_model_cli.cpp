// The cable_model command: JSON content, and clear errors for malformed states and options.
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cable_dynamics/tools/cable_model_app.h"

namespace {

const std::string kConfig = std::string(CABLE_CONFIG_DIR) + "/default.yaml";

struct ToolRun {
  int code;
  std::string out, err;
};

ToolRun run(std::vector<std::string> args) {
  args.insert(args.begin(), "cable_model");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = cable_dynamics::runCableModel(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

}  // namespace

TEST(CableModelCli, PrintsTheModelAsJson) {
  const ToolRun r = run({"--config", kConfig, "--set", "cable.links=2", "--q", "0.1,0.2,0.3,0.4,0.5,0.6", "--qd",
                     "1,0,0,0,0,-1"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["n"], 2);
  EXPECT_EQ(j["coordinates"][0], "joint_1_elevation");
  EXPECT_EQ(j["coordinates"][4], "joint_2_azimuth");
  EXPECT_EQ(j["coordinates"][5], "joint_2_torsion");
  EXPECT_DOUBLE_EQ(j["q"][3].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(j["qd"][5].get<double>(), -1.0);
  for (const char* key : {"M", "K", "D"}) {
    ASSERT_EQ(j[key].size(), 6u) << key;
    EXPECT_EQ(j[key][0].size(), 6u) << key;
  }
  for (const char* key : {"h", "G", "mass", "length", "inertia_transverse", "inertia_polar", "submerged_mass"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["mass"].size(), 2u);
  EXPECT_NEAR(j["length"][0].get<double>(), 25.0, 1e-12);
  EXPECT_TRUE(j.contains("load_mass") && j.contains("load_submerged_mass") && j.contains("gravity"));
}

TEST(CableModelCli, RandomStateIsAwayFromVerticalAndReproducible) {
  const ToolRun a = run({"--config", kConfig, "--random-state", "5"});
  const ToolRun b = run({"--config", kConfig, "--random-state", "5"});
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  const auto j = nlohmann::json::parse(a.out);
  for (int k = 0; k < j["n"].get<int>(); ++k) EXPECT_GE(j["q"][3 * k].get<double>(), 0.2);
}

TEST(CableModelCli, RejectsMalformedStates) {
  ToolRun r = run({"--config", kConfig, "--set", "cable.links=2", "--q", "0.1,0.2,0.3"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--q has 3 values: expected 3n = 6"), std::string::npos) << r.err;
  r = run({"--config", kConfig, "--set", "cable.links=1", "--q", "0.1,abc,0.3"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("entry 2 is 'abc'"), std::string::npos) << r.err;
  r = run({"--config", kConfig, "--set", "cable.links=1", "--qd", "0.1,nan,0.3"});
  EXPECT_EQ(r.code, 2);
  r = run({"--config", kConfig, "--set", "cable.links=1", "--q", "0.1,,0.3"});
  EXPECT_EQ(r.code, 2);
  r = run({"--config", kConfig, "--random-state", "-4"});
  EXPECT_EQ(r.code, 2);
}

TEST(CableModelCli, RejectsBadOptionsAndConfig) {
  EXPECT_EQ(run({}).code, 2);
  EXPECT_EQ(run({"--config", kConfig, "--bogus", "1"}).code, 2);
  EXPECT_EQ(run({"--config"}).code, 2);
  const ToolRun r = run({"--config", kConfig, "--set", "cable.links=0"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("cable.links"), std::string::npos) << r.err;
  EXPECT_EQ(run({"--help"}).code, 0);
}
