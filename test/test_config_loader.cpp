// Config loader: every documented bad value is rejected with the key named; good configs load.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/format_values.h"

using cable_dynamics::CableParams;
using cable_dynamics::ConfigError;
using cable_dynamics::loadConfigFile;
using cable_dynamics::loadConfigString;

namespace {

const std::string kDefault = std::string(CABLE_CONFIG_DIR) + "/default.yaml";

const char* const kMinimal = R"(
cable: {links: 4, length: 8.0, diameter: 0.02, mass_per_length: 0.5}
)";

/// Expects the override to be rejected with `key` named in both the exception and its message.
void expectRejected(const std::string& assignment, const std::string& key) {
  try {
    loadConfigString(kMinimal, {assignment});
    ADD_FAILURE() << assignment << " was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(ConfigLoader, ShippedConfigsLoad) {
  const CableParams p = loadConfigFile(kDefault);
  EXPECT_EQ(p.links, 25);
  EXPECT_NEAR(p.totalLength(), 50.0, 1e-12);
  EXPECT_EQ(p.link_lengths.size(), 25u);
  EXPECT_DOUBLE_EQ(p.diameter, 0.025);
  EXPECT_DOUBLE_EQ(p.fluid.density, 1025.0);
  EXPECT_EQ(p.simulation.integrator, cable_dynamics::Integrator::kRk4);
}

TEST(ConfigLoader, EveryShippedPresetLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CABLE_CONFIG_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(loadConfigFile(entry.path().string())) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(ConfigLoader, DefaultsForOptionalSections) {
  const CableParams p = loadConfigString(kMinimal);
  EXPECT_DOUBLE_EQ(p.gravity, 9.81);
  EXPECT_DOUBLE_EQ(p.load.mass, 0.0);
  EXPECT_DOUBLE_EQ(p.fluid.density, 1025.0);
  ASSERT_EQ(p.initial.elevation.size(), 4u);
  EXPECT_DOUBLE_EQ(p.initial.elevation[3], 0.0);
}

TEST(ConfigLoader, DerivedLinkProperties) {
  const CableParams p = loadConfigString(kMinimal, {"load.mass=3.0", "load.volume=0.001", "fluid.density=1000"});
  const auto props = cable_dynamics::deriveLinkProperties(p);
  const double r = 0.01, l = 2.0, m = 0.5 * l;
  ASSERT_EQ(props.n, 4);
  EXPECT_NEAR(props.length(2), l, 1e-15);
  EXPECT_NEAR(props.mass(0), m, 1e-15);
  EXPECT_NEAR(props.inertia_transverse(1), m * (l * l / 12.0 + r * r / 4.0), 1e-15);
  EXPECT_NEAR(props.inertia_polar(3), m * r * r / 2.0, 1e-15);
  EXPECT_NEAR(props.submerged_mass(0), m - 1000.0 * M_PI * r * r * l, 1e-12);
  EXPECT_NEAR(props.load_submerged_mass, 3.0 - 1.0, 1e-12);
}

TEST(ConfigLoader, LinkLengthsOverrideTotalLength) {
  const CableParams p = loadConfigString(kMinimal, {"cable.links=3", "cable.link_lengths=[1.0, 2.5, 0.7]"});
  ASSERT_EQ(p.link_lengths.size(), 3u);
  EXPECT_DOUBLE_EQ(p.link_lengths[1], 2.5);
  EXPECT_NEAR(p.totalLength(), 4.2, 1e-12);
}

TEST(ConfigLoader, MaterialDensityGivesMassPerLength) {
  const CableParams p = loadConfigString(R"(
cable: {links: 2, length: 1.0, diameter: 0.02, material_density: 1500.0}
)");
  EXPECT_NEAR(p.mass_per_length, 1500.0 * M_PI * 0.01 * 0.01, 1e-12);
}

TEST(ConfigLoader, RigiditiesGiveJointSprings) {
  const CableParams p = loadConfigString(kMinimal, {"cable.stiffness={model: bending, bending_rigidity: 10.0, torsional_rigidity: 4.0}"});
  const auto props = cable_dynamics::deriveLinkProperties(p);
  // Joint 1 spans the half link from the clamp to link 1's centre (1 m), the others link centre to
  // link centre (2 m): test_end_fixity holds this against closed forms.
  EXPECT_NEAR(props.stiffness_elevation(0), 10.0 / 1.0, 1e-12);
  EXPECT_NEAR(props.stiffness_azimuth(0), 10.0 / 1.0, 1e-12);
  EXPECT_NEAR(props.stiffness_elevation(1), 10.0 / 2.0, 1e-12);
  EXPECT_NEAR(props.stiffness_torsion(0), 4.0 / 1.0, 1e-12);
  EXPECT_NEAR(props.stiffness_torsion(3), 4.0 / 2.0, 1e-12);
  EXPECT_EQ(props.stiffness_model, cable_dynamics::StiffnessModel::kBending);
}

TEST(ConfigLoader, PerJointInitialLists) {
  const CableParams p = loadConfigString(kMinimal, {"initial.elevation=[0.1, 0.2, 0.3, 0.4]", "initial.torsion=0.5"});
  EXPECT_DOUBLE_EQ(p.initial.elevation[2], 0.3);
  EXPECT_DOUBLE_EQ(p.initial.torsion[3], 0.5);
}

TEST(ConfigLoader, RejectsBadLinkCount) {
  expectRejected("cable.links=0", "cable.links");
  expectRejected("cable.links=-3", "cable.links");
  expectRejected("cable.links=2.5", "cable.links");
  expectRejected("cable.links=many", "cable.links");
  expectRejected("cable.links=[1, 2]", "cable.links");
  expectRejected("cable.links=100000", "cable.links");
}

TEST(ConfigLoader, RejectsNonPositiveGeometryAndMass) {
  expectRejected("cable.length=0", "cable.length");
  expectRejected("cable.length=-5", "cable.length");
  expectRejected("cable.diameter=0", "cable.diameter");
  expectRejected("cable.diameter=-0.01", "cable.diameter");
  expectRejected("cable.mass_per_length=0", "cable.mass_per_length");
  expectRejected("cable.mass_per_length=-1", "cable.mass_per_length");
  expectRejected("cable.link_lengths=[1.0, 2.0, -1.0, 1.0]", "cable.link_lengths[2]");
  expectRejected("cable.link_lengths=[1.0, 2.0]", "cable.link_lengths");
  expectRejected("load.mass=-1", "load.mass");
  expectRejected("load.volume=-0.1", "load.volume");
  expectRejected("fluid.density=-1", "fluid.density");
}

TEST(ConfigLoader, RejectsNegativeStiffnessAndDamping) {
  expectRejected("cable.stiffness.elevation=-1", "cable.stiffness.elevation");
  expectRejected("cable.stiffness.azimuth=-1", "cable.stiffness.azimuth");
  expectRejected("cable.stiffness.torsion=-0.1", "cable.stiffness.torsion");
  expectRejected("cable.stiffness.bending_rigidity=-2", "cable.stiffness.bending_rigidity");
  expectRejected("cable.damping.elevation=-1", "cable.damping.elevation");
  expectRejected("cable.damping.torsion=-1", "cable.damping.torsion");
}

TEST(ConfigLoader, RejectsNonFiniteNumbers) {
  expectRejected("cable.length=.nan", "cable.length");
  expectRejected("cable.diameter=.inf", "cable.diameter");
  expectRejected("gravity=.nan", "gravity");
  expectRejected("fluid.current=[0, .nan, 0]", "fluid.current[1]");
  expectRejected("initial.elevation=.nan", "initial.elevation");
  expectRejected("cable.stiffness.elevation=.inf", "cable.stiffness.elevation");
}

TEST(ConfigLoader, RejectsWrongTypes) {
  expectRejected("cable.length=long", "cable.length");
  expectRejected("cable.length=[1, 2]", "cable.length");
  expectRejected("fluid.current=fast", "fluid.current");
  expectRejected("fluid.current=[1, 2]", "fluid.current");
  expectRejected("load.mode=floating", "load.mode");
  expectRejected("cable.stiffness.model=spring", "cable.stiffness.model");
  expectRejected("simulation.integrator=euler", "simulation.integrator");
  EXPECT_EQ(loadConfigString(kMinimal, {"simulation.integrator=semi_implicit"}).simulation.integrator, cable_dynamics::Integrator::kSemiImplicit);
  EXPECT_EQ(loadConfigString(kMinimal, {"simulation.integrator=implicit"}).simulation.integrator, cable_dynamics::Integrator::kImplicit);
  EXPECT_EQ(loadConfigString(kMinimal, {"simulation.rho_infinity=0.9"}).simulation.rho_infinity, 0.9);
  expectRejected("simulation.rho_infinity=1.5", "simulation.rho_infinity");
  expectRejected("simulation.rho_infinity=-0.1", "simulation.rho_infinity");
  expectRejected("simulation.dt=0", "simulation.dt");
  expectRejected("initial.azimuth=[0.1, 0.2]", "initial.azimuth");
  expectRejected("cable.stiffness=3", "cable.stiffness");
}

TEST(ConfigLoader, RejectsUnknownKeys) {
  expectRejected("cable.lenght=3", "cable.lenght");
  expectRejected("fluid.densty=1000", "fluid.densty");
  expectRejected("cable.stiffness.bend=1", "cable.stiffness.bend");
  expectRejected("solver.dt=0.1", "solver");
}

TEST(ConfigLoader, MotionsAndCurrentProfile) {
  const CableParams p = loadConfigString(kMinimal, {"base.motion={amplitude: [0, 0, 1.0], period: 8.0}",
                                                    "load.mode=attached", "load.motion.velocity=[0.1, 0, 0]",
                                                    "fluid.current=[0, 0, 0]",
                                                    "fluid.current_profile=[[0, 1.0, 0, 0], [20, 0.2, 0, 0]]"});
  EXPECT_DOUBLE_EQ(p.base.motion.amplitude.z(), 1.0);
  EXPECT_DOUBLE_EQ(p.base.motion.period, 8.0);
  EXPECT_DOUBLE_EQ(p.load.motion.velocity.x(), 0.1);
  EXPECT_EQ(p.load.mode, cable_dynamics::LoadMode::kAttached);
  ASSERT_EQ(p.fluid.current_profile.size(), 2u);
  EXPECT_DOUBLE_EQ(p.fluid.current_profile[1](0), 20.0);
  EXPECT_DOUBLE_EQ(p.fluid.current_profile[1](1), 0.2);
}

TEST(ConfigLoader, RejectsBadMotionsAndProfiles) {
  expectRejected("base.motion.period=0", "base.motion.period");
  expectRejected("base.motion.amplitude=[1, 2]", "base.motion.amplitude");
  expectRejected("base.motion.phase=7", "base.motion.phase");  // beyond 2 pi
  expectRejected("base.motion.speed=1", "base.motion.speed");  // no such key
  expectRejected("load.coupling.stiffness=0", "load.coupling.stiffness");
  expectRejected("load.coupling.damping=-1", "load.coupling.damping");
  expectRejected("fluid.current_profile=[[10, 1, 0, 0], [5, 1, 0, 0]]", "fluid.current_profile[1]");
  expectRejected("fluid.current_profile=[[10, 1, 0]]", "fluid.current_profile[0].row");
  expectRejected("fluid.current_profile=fast", "fluid.current_profile");
  expectRejected("fluid.drag_points=9", "fluid.drag_points");
  expectRejected("simulation.duration=-1", "simulation.duration");
  try {
    loadConfigString(kMinimal, {"fluid.current=[1, 0, 0]", "fluid.current_profile=[[0, 1, 0, 0]]"});
    ADD_FAILURE() << "current with a profile accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "fluid.current");
  }
}

TEST(ConfigLoader, RejectsAmbiguousPairs) {
  expectRejected("cable.material_density=1500", "cable.mass_per_length");
  expectRejected("cable.stiffness={elevation: 1.0, bending_rigidity: 2.0}", "cable.stiffness.bending_rigidity");
}

TEST(ConfigLoader, RejectsMissingRequiredKeys) {
  try {
    loadConfigString("cable: {links: 3, diameter: 0.02, mass_per_length: 0.5}");
    ADD_FAILURE() << "missing length accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "cable.length");
  }
  EXPECT_THROW(loadConfigString("gravity: 9.81"), ConfigError);
}

TEST(ConfigLoader, RejectsMalformedOverride) {
  EXPECT_THROW(loadConfigString(kMinimal, {"cable.links"}), ConfigError);
  EXPECT_THROW(loadConfigString(kMinimal, {"cable..links=3"}), ConfigError);
  EXPECT_THROW(loadConfigString(kMinimal, {"cable.links.x=3"}), ConfigError);
}

TEST(ConfigLoader, MissingFileIsAConfigError) {
  EXPECT_THROW(loadConfigFile("/nonexistent/cable.yaml"), ConfigError);
}

TEST(ConfigLoader, BaseFixityAndClampDirection) {
  const CableParams p = loadConfigString(kMinimal, {"cable.stiffness.model=bending", "base.direction=[0, 3, -4]"});
  EXPECT_EQ(p.base.fixity, cable_dynamics::BaseFixity::kClamped);
  EXPECT_NEAR(p.base.direction.y(), 0.6, 1e-15);  // normalized
  const auto props = cable_dynamics::deriveLinkProperties(p);
  EXPECT_NEAR(props.clamp_axis.y(), -0.6, 1e-15);  // paper frame: y and z flip
  EXPECT_NEAR(props.clamp_axis.z(), 0.8, 1e-15);
  const CableParams pinned = loadConfigString(
      kMinimal, {"cable.stiffness={model: bending, bending_rigidity: 5.0}", "cable.damping.elevation=1", "base.fixity=pinned"});
  const auto pinned_props = cable_dynamics::deriveLinkProperties(pinned);
  EXPECT_EQ(pinned_props.stiffness_elevation(0), 0.0);  // a pin holds link 1 by a force alone
  EXPECT_EQ(pinned_props.damping_elevation(0), 0.0);
  EXPECT_GT(pinned_props.stiffness_elevation(1), 0.0);
  expectRejected("base.fixity=welded", "base.fixity");
  expectRejected("base.direction=[0, 0, 0]", "base.direction");
  expectRejected("base.direction=[0, 1]", "base.direction");
  // The paper's springs are measured from the vertical: neither a pin nor a tilted clamp applies.
  expectRejected("base.fixity=pinned", "base.fixity");
  expectRejected("base.direction=[1, 0, 0]", "base.direction");
}

TEST(ConfigLoader, RefusalsPrintTheValueAtFullPrecision) {
  // Issue 27: refusals printed numbers with std::to_string's 6 decimals, so a value just off a bound read
  // as the bound itself ("20.000000 ... adding up to 20"). formatNumber prints the shortest digits that
  // read back as the same double.
  using cable_dynamics::formatNumber;
  EXPECT_EQ(formatNumber(19.999999999), "19.999999999");
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(std::stod(formatNumber(1.0 / 3.0)), 1.0 / 3.0);
  const std::string config =
      "cable: {links: 4, length: 20.0, diameter: 0.03, mass_per_length: 0.8,\n"
      "        sections: [{length: 9.9999999}, {length: 10.0}]}\n";
  try {
    loadConfigString(config);
    ADD_FAILURE() << "sections adding up to 19.9999999 m of a 20 m cable were accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("they add up to 19.9999999 m"), std::string::npos) << e.what();
  }
}
