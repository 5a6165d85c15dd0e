// docs/CONFIG.md against the config loader: every key the loader asks for is a row of CONFIG.md's key
// table, and every row names a key the loader asks for. The loader's keys are recorded by ConfigKeyLog
// (params/config_section.h) while it parses configs that take each of its branches (a winch with a
// schedule, sections, a current profile, a seabed grid; attachments, which a winch excludes), so a key
// added to the loader without a row, or a row left behind by a removed key, fails here.
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/config_section.h"

using namespace cable_dynamics;

namespace {

// Between them they reach every read of the loader: optional keys are asked for (has()) whether or not
// they are given, so these configs only need the branches that open further keys.
const char* const kWinchConfig = R"(
cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 1.0,
        stiffness: {model: bending, bending_rigidity: 10.0, torsional_rigidity: 5.0},
        damping: {elevation: 0.1, azimuth: 0.1, torsion: 0.1},
        limits: {max_tension: 1.0e4, min_bend_radius: 1.0, min_seabed_clearance: 0.5},
        sections: [{length: 4.0, diameter: 0.03, mass_per_length: 1.0, bending_rigidity: 10.0,
                    torsional_rigidity: 5.0, drag_normal: 1.0, drag_tangential: 0.01, added_mass: 1.0,
                    limits: {min_bend_radius: 2.0}},
                   {material_density: 2000.0}]}
load: {mass: 10.0, volume: 0.001, mode: attached, fixity: clamped, direction: [0, 0, -1], drag_area: 0.1,
       added_mass: 1.0, coupling: {stiffness: 1.0e4, damping: 1.0e3}, attachment: [0, 0, 0],
       motion: {offset: [0, 0, 0], amplitude: [0, 0, 0], period: 10.0, phase: 0.0, velocity: [0, 0, 0],
                attitude_amplitude: [0, 0, 0], attitude_phase: [0, 0, 0]}}
base: {hang_off: [0, 0, 0], fixity: clamped, direction: [0, 0, -1], motion: {period: 10.0}}
fluid: {density: 1025.0, drag_normal: 1.2, drag_tangential: 0.01, added_mass: 1.0, drag_points: 3,
        current_profile: [[0.0, 0.1, 0.0, 0.0], [100.0, 0.0, 0.0, 0.0]]}
gravity: 9.81
seabed: {grid: {origin: [-50, -50], spacing: [100, 100], depth: [[30, 30], [30, 30]]}, penetration: 0.01,
         stiffness: 0.0, damping_ratio: 0.5, friction: {axial: 0.1, lateral: 0.2, velocity: 0.01}, contact_points: 4}
initial: {mode: angles, elevation: 0.0, azimuth: 0.0, torsion: 0.0}
simulation: {dt: 0.001, integrator: rk4, rho_infinity: 0.9, duration: 1.0, formulation: recursive}
winch: {max_length: 12.0, min_length: 2.0, max_speed: 1.0, max_acceleration: 0.5, speed: 0.0,
        schedule: [{time: 1.0, speed: 0.5}, {time: 2.0, length: 10.0}]}
)";

const char* const kAttachmentConfig = R"(
cable: {links: 4, link_lengths: [1.0, 1.0, 1.0, 1.0], length: 4.0, diameter: 0.03, material_density: 2000.0}
attachments: [{arc_length: 2.0, mass: 1.0, volume: 0.01, drag_area: 0.1, added_mass: 0.5}]
seabed: {depth: 30.0}
fluid: {current: [0.1, 0.0, 0.0]}
)";

/// `a[3].b` -> `a[i].b`; a list row the loader reads through a wrapper (`fluid.current_profile[i].row`,
/// config_loader.cpp) is the list's own key.
const char* const kBodyConfig = R"(
cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 1.0}
load: {mass: 11.5, volume: 0.0112, mode: body, attachment: [-0.2, 0.0, 0.1],
       body: {inertia: [0.16, 0.16, 0.16], added_mass: [5.5, 12.7, 14.57, 0.12, 0.12, 0.12],
              linear_damping: [4.03, 6.22, 5.18, 0.07, 0.07, 0.07], quadratic_damping: [18.18, 21.66, 36.99, 1.55, 1.55, 1.55],
              center_of_gravity: [0, 0, 0], center_of_buoyancy: [0, 0, 0.02], initial_attitude: [0, 0, 0],
              station_keeping: {position_gain: [50, 50, 50], velocity_gain: [40, 40, 40], integral_gain: [10, 10, 10], attitude_gain: [0, 0, 5],
                                rate_gain: [0, 0, 2], max_force: 80.0, max_torque: 10.0}}}
)";

std::string normalized(const std::string& key) {
  std::string k = std::regex_replace(key, std::regex(R"(\[[0-9]+\])"), "[i]");
  const std::string wrapper = "[i].row";
  if (k.size() > wrapper.size() && k.compare(k.size() - wrapper.size(), wrapper.size(), wrapper) == 0) {
    k.erase(k.size() - wrapper.size());
  }
  return k;
}

std::set<std::string> loaderKeys() {
  // One log over both parses: a mapping one config opens (seabed.grid, winch) is a section in both.
  ConfigKeyLog log;
  for (const char* config : {kWinchConfig, kAttachmentConfig, kBodyConfig}) loadConfigString(config);
  std::set<std::string> keys;
  for (const std::string& k : log.keys()) keys.insert(normalized(k));
  return keys;
}

/// The first cell of every row of the table under "## Keys" in docs/CONFIG.md: `key`.
std::set<std::string> documentedKeys() {
  std::ifstream file(CABLE_DOCS_DIR "/CONFIG.md");
  EXPECT_TRUE(file.good()) << CABLE_DOCS_DIR "/CONFIG.md";
  std::set<std::string> keys;
  bool in_keys = false;
  const std::regex row(R"(^\| `([^`]+)` \|)");
  for (std::string line; std::getline(file, line);) {
    if (line.rfind("## ", 0) == 0) in_keys = line == "## Keys";
    std::smatch m;
    if (in_keys && std::regex_search(line, m, row)) {
      EXPECT_TRUE(keys.insert(m[1]).second) << "docs/CONFIG.md names " << m[1] << " twice";
    }
  }
  return keys;
}

}  // namespace

TEST(ConfigKeys, TheLoaderAndDocsConfigNameTheSameKeys) {
  const std::set<std::string> loader = loaderKeys(), docs = documentedKeys();
  ASSERT_GT(loader.size(), 80u) << "the configs above no longer reach the loader's keys";
  for (const std::string& k : loader) EXPECT_EQ(docs.count(k), 1u) << "the loader reads " << k << ", docs/CONFIG.md does not name it";
  for (const std::string& k : docs) EXPECT_EQ(loader.count(k), 1u) << "docs/CONFIG.md names " << k << ", the loader does not read it";
}

// One range per key: every key the loader reads with a range, the gate (checkConfigRanges, which the
// loader runs at its end and the simulator on parameters filled in by hand) checks too; and the gate
// names only keys a config has. The loader reads the same keys as above and the log records both.
TEST(ConfigKeys, TheGateChecksEveryKeyTheLoaderReadsWithARange) {
  std::set<std::string> ranged, checked, asked;
  {
    ConfigKeyLog log;
    for (const char* config : {kWinchConfig, kAttachmentConfig, kBodyConfig}) loadConfigString(config);
    for (const std::string& k : log.rangedKeys()) ranged.insert(normalized(k));
    for (const std::string& k : log.checkedKeys()) checked.insert(normalized(k));
    for (const std::string& k : log.keys()) asked.insert(normalized(k));
  }
  // Not kept in CableParams: the loader turns a material density into the mass per length, which the
  // gate checks.
  const std::set<std::string> not_kept = {"cable.material_density", "cable.sections[i].material_density"};
  ASSERT_GE(ranged.size(), 100u) << "the configs above no longer reach the loader's ranged keys";
  for (const std::string& k : ranged) {
    EXPECT_TRUE(checked.count(k) == 1 || not_kept.count(k) == 1) << "the loader reads " << k << " with a range, the gate does not check it";
  }
  for (const std::string& k : checked) EXPECT_EQ(asked.count(k), 1u) << "the gate checks " << k << ", which no config names";
}

// The hook itself: it records what a parse asks for and nothing once it is gone.
TEST(ConfigKeys, TheLogRecordsWhileItExists) {
  {
    ConfigKeyLog log;
    loadConfigString("cable: {links: 1, length: 1.0, diameter: 0.01, mass_per_length: 1.0}");
    const std::set<std::string> keys = log.keys();
    EXPECT_EQ(keys.count("cable.links"), 1u);
    EXPECT_EQ(keys.count("cable.stiffness.model"), 1u);
    EXPECT_EQ(keys.count("cable"), 0u) << "a section is not a key";
  }
  ConfigKeyLog later;
  EXPECT_TRUE(later.keys().empty());
}
