#include "seabed_config.h"

#include <algorithm>
#include <cmath>

#include <yaml-cpp/yaml.h>

namespace cable_dynamics {
namespace {

/// The grid's keys (inline under seabed.grid, or the whole of a grid file): origin [x0, y0] [m],
/// spacing [dx, dy] [m], depth: rows along y, each a list along x [m].
SeabedGrid parseGrid(ConfigSection grid) {
  SeabedGrid g;
  const std::vector<double> origin = grid.numberList("origin", 2, ranges::kGridOrigin);
  const std::vector<double> spacing = grid.numberList("spacing", 2, ranges::kGridSpacing);
  g.origin = {origin[0], origin[1]};
  g.spacing = {spacing[0], spacing[1]};
  const std::string key = grid.path() + ".depth";
  const YAML::Node rows = grid.raw("depth");
  const std::string expected = "a list of at least 2 rows (along y), each a list of the same number (at least 2) of depths [m]";
  if (!rows.IsSequence() || rows.size() < 2) throw ConfigError(key, describeNode(rows), expected);
  const int ny = static_cast<int>(rows.size());
  const int nx = rows[0].IsSequence() ? static_cast<int>(rows[0].size()) : 0;
  if (nx < 2) throw ConfigError(key + "[0]", describeNode(rows[0]), expected);
  g.depth.resize(ny, nx);
  for (int j = 0; j < ny; ++j) {
    const std::string row_key = key + "[" + std::to_string(j) + "]";
    if (!rows[j].IsSequence() || static_cast<int>(rows[j].size()) != nx) {
      throw ConfigError(row_key, describeNode(rows[j]), "a list of " + std::to_string(nx) + " depths [m] (as row 0)");
    }
    for (int i = 0; i < nx; ++i) {
      double value = 0.0;
      const YAML::Node cell = rows[j][i];
      const bool plain = cell.IsScalar() && cell.Tag() != "!";  // a quoted '25' is not a number
      if (!plain || !YAML::convert<double>::decode(cell, value) || !ranges::kGridDepth.allows(value)) {
        throw ConfigError(row_key + "[" + std::to_string(i) + "]", describeNode(cell), ranges::kGridDepth.text());
      }
      g.depth(j, i) = value;
    }
  }
  grid.rejectUnknownKeys();
  return g;
}

double largestDiameter(const CableParams& p) {
  double d = p.diameter;
  for (const SectionParams& s : p.sections) d = std::max(d, s.diameter);
  return d;
}

}  // namespace

void parseSeabed(ConfigSection seabed, const std::string& base_dir, CableParams& p) {
  SeabedParams& s = p.seabed;
  s.enabled = true;
  const bool has_depth = seabed.has("depth");
  const bool has_grid = seabed.has("grid"), has_file = seabed.has("grid_file");
  if (int(has_depth) + int(has_grid) + int(has_file) != 1) {
    throw ConfigError(seabed.path(), has_depth || has_grid || has_file ? "more than one of depth, grid, grid_file" : "no depth",
                      "exactly one of seabed.depth [m] (flat), seabed.grid or seabed.grid_file (bathymetry)");
  }
  if (has_depth) s.depth = seabed.number("depth", 0.0, ranges::kSeabedDepth);
  if (has_grid) {
    s.has_grid = true;
    s.grid = parseGrid(seabed.sub("grid"));
  }
  if (has_file) {
    std::string path = seabed.text("grid_file", "", [](const std::string& t) { return !t.empty(); }, "a YAML file's path");
    if (path.front() != '/' && !base_dir.empty()) path = base_dir + "/" + path;
    YAML::Node file;
    try {
      file = YAML::LoadFile(path);
    } catch (const YAML::Exception& e) {
      throw ConfigError(seabed.path() + ".grid_file", path, std::string("a readable YAML grid file: ") + e.what());
    }
    s.has_grid = true;
    s.grid = parseGrid(ConfigSection(file, path));
  }
  const double diameter = largestDiameter(p);
  s.penetration = seabed.number("penetration", 0.5 * diameter, ranges::kPenetration);
  s.stiffness = seabed.number("stiffness", 0.0, ranges::kSeabedStiffness);
  s.damping_ratio = seabed.number("damping_ratio", 0.5, ranges::kDampingRatio);
  ConfigSection friction = seabed.sub("friction");
  s.friction_axial = friction.number("axial", 0.0, ranges::kFriction);
  s.friction_lateral = friction.number("lateral", 0.0, ranges::kFriction);
  s.friction_velocity = friction.number("velocity", 0.01, ranges::kFrictionVelocity);
  s.friction_breakout = friction.number("breakout", 0.005, ranges::kFrictionBreakout);
  friction.rejectUnknownKeys();
  s.contact_points = seabed.integer("contact_points", 4, ranges::kContactPoints);
  seabed.rejectUnknownKeys();
}

}  // namespace cable_dynamics
