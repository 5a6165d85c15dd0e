#include "cable_dynamics/params/config_loader.h"

#include <cmath>
#include <limits>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/params/input_gate.h"
#include "seabed_config.h"

namespace cable_dynamics {
namespace {

using Section = ConfigSection;

constexpr int kMaxLinks = 10000;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// What parseCable leaves for later: the sections' defaults need the fluid's coefficients.
struct CableRest {
  bool has_sections = false;
  YAML::Node sections;            ///< cable.sections when has_sections
  double material_density = 0.0;  ///< [kg/m^3] when the cable is given by material_density
};

void parseCable(Section cable, CableParams& p, CableRest& rest) {
  p.links = cable.integer("links", 1, 1, kMaxLinks, true);
  if (cable.has("link_lengths")) {
    // The list overrides `length`: the total length is then the sum of the list.
    p.link_lengths = cable.numberList("link_lengths", p.links, 0.0, 1e5, true, "m");
    cable.number("length", 0.0, 0.0, 1e5, true, "m");  // still validated when present
  } else {
    const double total = cable.number("length", 0.0, 0.0, 1e5, true, "m", true);
    p.link_lengths.assign(p.links, total / p.links);
  }
  p.diameter = cable.number("diameter", 0.0, 0.0, 10.0, true, "m", true);
  const bool has_linear_density = cable.has("mass_per_length");
  const bool has_material_density = cable.has("material_density");
  if (has_linear_density == has_material_density) {
    throw ConfigError(cable.path() + ".mass_per_length", has_linear_density ? "given with material_density" : "(missing)",
                      "exactly one of cable.mass_per_length [kg/m] or cable.material_density [kg/m^3]");
  }
  if (has_linear_density) {
    p.mass_per_length = cable.number("mass_per_length", 0.0, 0.0, 1e5, true, "kg/m");
  } else {
    const double rho = cable.number("material_density", 0.0, 0.0, 1e5, true, "kg/m^3");
    p.mass_per_length = rho * M_PI * 0.25 * p.diameter * p.diameter;
    rest.material_density = rho;
  }
  p.axial_stiffness = cable.number("axial_stiffness", 0.0, 0.0, 1e13, false, "N");
  p.axial_damping = cable.number("axial_damping", 0.0, 0.0, 1e13, false, "N s");
  {
    // Each limit, when given, must be positive (the clearance may be 0); absent: no limit.
    Section limits = cable.sub("limits");
    LimitParams& l = p.limits;
    if (limits.has("max_tension")) l.max_tension = limits.number("max_tension", 0.0, 0.0, 1e12, true, "N");
    if (limits.has("min_bend_radius")) l.min_bend_radius = limits.number("min_bend_radius", 0.0, 0.0, 1e5, true, "m");
    l.has_min_seabed_clearance = limits.has("min_seabed_clearance");
    if (l.has_min_seabed_clearance) {
      l.min_seabed_clearance = limits.number("min_seabed_clearance", 0.0, 0.0, 1e5, false, "m");
    }
    limits.rejectUnknownKeys();
  }
  if (cable.has("sections")) {
    rest.has_sections = true;
    rest.sections = cable.raw("sections");
  }

  Section stiffness = cable.sub("stiffness");
  const std::string model = stiffness.choice("model", "paper", {"paper", "bending"});
  p.stiffness.model = model == "paper" ? StiffnessModel::kPaper : StiffnessModel::kBending;
  p.stiffness.elevation = stiffness.number("elevation", 0.0, 0.0, kInf, false, "N m/rad");
  p.stiffness.azimuth = stiffness.number("azimuth", 0.0, 0.0, kInf, false, "N m/rad");
  p.stiffness.torsion = stiffness.number("torsion", 0.0, 0.0, kInf, false, "N m/rad");
  p.stiffness.bending_rigidity = stiffness.number("bending_rigidity", 0.0, 0.0, kInf, false, "N m^2");
  p.stiffness.torsional_rigidity = stiffness.number("torsional_rigidity", 0.0, 0.0, kInf, false, "N m^2");
  stiffness.rejectUnknownKeys();

  Section damping = cable.sub("damping");
  p.damping.elevation = damping.number("elevation", 0.0, 0.0, kInf, false, "N m s/rad");
  p.damping.azimuth = damping.number("azimuth", 0.0, 0.0, kInf, false, "N m s/rad");
  p.damping.torsion = damping.number("torsion", 0.0, 0.0, kInf, false, "N m s/rad");
  damping.rejectUnknownKeys();
  cable.rejectUnknownKeys();
}

Eigen::Vector3d vector3(Section& s, const std::string& key, double limit, const char* unit) {
  if (!s.has(key)) return Eigen::Vector3d::Zero();
  const std::vector<double> v = s.numberList(key, 3, -limit, limit, false, unit);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

MotionParams parseMotion(Section motion) {
  MotionParams m;
  m.offset = vector3(motion, "offset", 1e5, "m");
  m.amplitude = vector3(motion, "amplitude", 1e4, "m");
  m.period = motion.number("period", 10.0, 0.0, 1e6, true, "s");
  m.phase = motion.number("phase", 0.0, -2.0 * M_PI, 2.0 * M_PI, false, "rad");
  m.velocity = vector3(motion, "velocity", 100.0, "m/s");
  m.attitude_amplitude = vector3(motion, "attitude_amplitude", M_PI, "rad");
  m.attitude_phase = vector3(motion, "attitude_phase", 2.0 * M_PI, "rad");
  motion.rejectUnknownKeys();
  return m;
}

/// A square matrix given whole (size^2 numbers, row by row) or by its diagonal (size numbers); `fallback`
/// when absent.
template <int Size>
Eigen::Matrix<double, Size, Size> squareMatrix(Section& s, const std::string& key, double limit, const char* unit,
                                               const Eigen::Matrix<double, Size, Size>& fallback) {
  if (!s.has(key)) return fallback;
  Eigen::Matrix<double, Size, Size> m = Eigen::Matrix<double, Size, Size>::Zero();
  const bool whole = s.raw(key).IsSequence() && s.raw(key).size() == static_cast<std::size_t>(Size * Size);
  const std::vector<double> v = s.numberList(key, whole ? Size * Size : Size, -limit, limit, false, unit);
  for (int r = 0; r < Size; ++r) {
    if (!whole) m(r, r) = v[r];
    for (int c = 0; whole && c < Size; ++c) m(r, c) = v[Size * r + c];
  }
  return m;
}

/// What load.body holds: the ROV's matrices, damping, centres and station keeper (cable_params.h).
/// Symmetry and definiteness are the gate's (input_gate.cpp), which names the key.
RovBodyParams parseRovBody(Section body) {
  RovBodyParams b;
  b.inertia = squareMatrix<3>(body, "inertia", 1e9, "kg m^2", b.inertia);
  b.added_mass = squareMatrix<6>(body, "added_mass", 1e9, "kg, kg m, kg m^2", b.added_mass);
  const auto six = [&body](const char* key, double lo, const char* unit) {
    Eigen::Matrix<double, 6, 1> v = Eigen::Matrix<double, 6, 1>::Zero();
    if (!body.has(key)) return v;
    const std::vector<double> list = body.numberList(key, 6, lo, 1e9, false, unit);
    for (int i = 0; i < 6; ++i) v(i) = list[i];
    return v;
  };
  b.linear_damping = six("linear_damping", 0.0, "N s/m, N m s/rad");
  b.quadratic_damping = six("quadratic_damping", 0.0, "N s^2/m^2, N m s^2/rad^2");
  b.center_of_gravity = vector3(body, "center_of_gravity", 100.0, "m");
  b.center_of_buoyancy = vector3(body, "center_of_buoyancy", 100.0, "m");
  b.initial_attitude = vector3(body, "initial_attitude", M_PI, "rad");
  Section keeper = body.sub("station_keeping");
  const auto gains = [&keeper](const char* key, const char* unit) {
    if (!keeper.has(key)) return Eigen::Vector3d::Zero().eval();
    const std::vector<double> v = keeper.numberList(key, 3, 0.0, 1e9, false, unit);
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  b.position_gain = gains("position_gain", "N/m");
  b.velocity_gain = gains("velocity_gain", "N s/m");
  b.integral_gain = gains("integral_gain", "N/(m s)");
  b.attitude_gain = gains("attitude_gain", "N m/rad");
  b.rate_gain = gains("rate_gain", "N m s/rad");
  b.max_force = keeper.number("max_force", 1e300, 0.0, 1e300, false, "N");
  b.max_torque = keeper.number("max_torque", 1e300, 0.0, 1e300, false, "N m");
  keeper.rejectUnknownKeys();
  body.rejectUnknownKeys();
  return b;
}

void parseLoad(Section load, CableParams& p) {
  p.load.mass = load.number("mass", 0.0, 0.0, 1e7, false, "kg");
  p.load.volume = load.number("volume", 0.0, 0.0, 1e4, false, "m^3");
  const std::string mode = load.choice("mode", "free", {"free", "anchored", "attached", "body"});
  p.load.mode = mode == "free"       ? LoadMode::kFree
                : mode == "anchored" ? LoadMode::kAnchored
                : mode == "attached" ? LoadMode::kAttached
                                     : LoadMode::kBody;
  if (load.has("body")) p.load.body = parseRovBody(load.sub("body"));
  p.load.drag_area = load.number("drag_area", 0.0, 0.0, 1e4, false, "m^2");
  p.load.added_mass = load.number("added_mass", 0.0, 0.0, 1e7, false, "kg");
  if (load.has("anchor") && p.load.mode != LoadMode::kAnchored) {
    throw ConfigError("load.anchor", describeNode(load.raw("anchor")), "given only with load.mode: anchored");
  }
  p.load.anchor = load.choice("anchor", "exact", {"exact", "spring"}) == "exact" ? AnchorHold::kExact : AnchorHold::kSpring;
  if (p.load.heldExactly() && load.has("coupling")) {
    // The exact hold has no gains: a coupling given here would be silently unused.
    throw ConfigError("load.coupling", describeNode(load.raw("coupling")),
                      "absent with load.mode anchored: the anchor holds its point exactly (load.anchor: spring for an "
                      "anchor that gives by the coupling)");
  }
  Section coupling = load.sub("coupling");
  p.load.coupling_stiffness = coupling.number("stiffness", 2.0e4, 0.0, 1e9, true, "N/m");
  p.load.coupling_damping = coupling.number("damping", 2.0e3, 0.0, 1e9, false, "N s/m");
  coupling.rejectUnknownKeys();
  p.load.motion = parseMotion(load.sub("motion"));
  p.load.attachment = vector3(load, "attachment", 1e3, "m");
  p.load.fixity = load.choice("fixity", "pinned", {"pinned", "clamped"}) == "pinned" ? TipFixity::kPinned : TipFixity::kClamped;
  if (load.has("direction")) {
    const std::vector<double> d = load.numberList("direction", 3, -1e3, 1e3, false, "");
    p.load.direction = Eigen::Vector3d(d[0], d[1], d[2]);
    if (p.load.direction.norm() < 1e-9) {
      throw ConfigError("load.direction", describeNode(load.raw("direction")), "a non-zero vector");
    }
    p.load.direction.normalize();
  }
  load.rejectUnknownKeys();
}

void parseFluid(Section fluid, CableParams& p) {
  p.fluid.density = fluid.number("density", 1025.0, 0.0, 2.0e4, false, "kg/m^3");
  p.fluid.drag_normal = fluid.number("drag_normal", 1.2, 0.0, 100.0, false, "");
  p.fluid.drag_tangential = fluid.number("drag_tangential", 0.01, 0.0, 100.0, false, "");
  p.fluid.added_mass = fluid.number("added_mass", 1.0, 0.0, 100.0, false, "");
  p.fluid.current = vector3(fluid, "current", kMaxCurrentSpeed, "m/s");  // the setter's range too
  p.fluid.drag_points = fluid.integer("drag_points", 3, 1, 8, false);
  if (fluid.has("current_profile")) {
    const YAML::Node rows = fluid.raw("current_profile");
    const std::string key = fluid.path() + ".current_profile";
    if (!rows.IsSequence() || rows.size() < 1) {
      throw ConfigError(key, describeNode(rows), "a list of [depth m, current x, y, z m/s] rows");
    }
    double previous_depth = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      YAML::Node wrapper;
      wrapper["row"] = rows[i];
      Section row(wrapper, key + "[" + std::to_string(i) + "]");
      const std::vector<double> v = row.numberList("row", 4, -1e5, 1e5, false, "m, m/s");
      if (!(v[0] > previous_depth)) {
        throw ConfigError(key + "[" + std::to_string(i) + "]", describeNode(rows[i]), "depths strictly increasing");
      }
      previous_depth = v[0];
      p.fluid.current_profile.emplace_back(v[0], v[1], v[2], v[3]);
    }
    if (!p.fluid.current.isZero()) {
      throw ConfigError(fluid.path() + ".current", describeNode(fluid.raw("current")),
                        "[0, 0, 0] or absent when current_profile is given (one or the other)");
    }
  }
  fluid.rejectUnknownKeys();
}

/// `cable.sections` (after the fluid: a key left out takes the cable's or the fluid's value).
void parseSections(const YAML::Node& rows, const CableRest& rest, CableParams& p) {
  const std::string key = "cable.sections";
  if (!rows.IsSequence() || rows.size() < 1) {
    throw ConfigError(key, describeNode(rows), "a list of {length: m, diameter: m, mass_per_length: kg/m, ...}");
  }
  const double total = p.totalLength();  // before a winch adds its drum's slots
  const StiffnessParams& k = p.stiffness;
  double sum = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Section row(rows[i], key + "[" + std::to_string(i) + "]");
    const bool last = i + 1 == rows.size();
    SectionParams s;
    // Every length but the last is required; the last, when left out, runs to the cable's tip.
    s.length = row.number("length", 0.0, 0.0, 1e5, true, "m", !last);
    s.diameter = row.number("diameter", p.diameter, 0.0, 10.0, true, "m");
    const bool linear = row.has("mass_per_length"), material = row.has("material_density");
    if (linear && material) {
      throw ConfigError(row.path() + ".mass_per_length", "given with material_density",
                        "at most one of mass_per_length [kg/m] or material_density [kg/m^3]");
    }
    if (linear) {
      s.mass_per_length = row.number("mass_per_length", 0.0, 0.0, 1e5, true, "kg/m");
    } else {
      // Left out: the cable's material density over this diameter, or the cable's mass per length.
      const double rho = material ? row.number("material_density", 0.0, 0.0, 1e5, true, "kg/m^3") : rest.material_density;
      s.mass_per_length = rho > 0.0 ? rho * M_PI * 0.25 * s.diameter * s.diameter : p.mass_per_length;
    }
    s.bending_rigidity = row.number("bending_rigidity", k.bending_rigidity, 0.0, kInf, false, "N m^2");
    s.torsional_rigidity = row.number("torsional_rigidity", k.torsional_rigidity, 0.0, kInf, false, "N m^2");
    if (row.has("bending_rigidity") && s.bending_rigidity > 0.0 && (k.elevation > 0.0 || k.azimuth > 0.0)) {
      throw ConfigError(row.path() + ".bending_rigidity", formatNumber(s.bending_rigidity),
                        "0 when cable.stiffness.elevation or azimuth is given (one or the other)");
    }
    if (row.has("torsional_rigidity") && s.torsional_rigidity > 0.0 && k.torsion > 0.0) {
      throw ConfigError(row.path() + ".torsional_rigidity", formatNumber(s.torsional_rigidity),
                        "0 when cable.stiffness.torsion is given (one or the other)");
    }
    s.axial_stiffness = row.number("axial_stiffness", p.axial_stiffness, 0.0, 1e13, false, "N");
    s.drag_normal = row.number("drag_normal", p.fluid.drag_normal, 0.0, 100.0, false, "");
    s.drag_tangential = row.number("drag_tangential", p.fluid.drag_tangential, 0.0, 100.0, false, "");
    s.added_mass = row.number("added_mass", p.fluid.added_mass, 0.0, 100.0, false, "");
    s.min_bend_radius = p.limits.min_bend_radius;  // the cable's unless the section has its own
    {
      Section limits = row.sub("limits");
      if (limits.has("min_bend_radius")) s.min_bend_radius = limits.number("min_bend_radius", 0.0, 0.0, 1e5, true, "m");
      limits.rejectUnknownKeys();
    }
    row.rejectUnknownKeys();
    if (last && !row.has("length")) {
      if (!(total - sum > 1e-9 * total)) {
        throw ConfigError(row.path() + ".length", "(missing)",
                          "the rest of the cable, but the sections before it already take " + formatNumber(sum) +
                              " m of " + formatNumber(total) + " m");
      }
      s.length = total - sum;
    }
    sum += s.length;
    if (sum > total * (1.0 + 1e-9) || (last && std::abs(sum - total) > 1e-9 * total)) {
      throw ConfigError(row.path() + ".length", formatNumber(s.length),
                        "section lengths adding up to the cable's length " + formatNumber(total) + " m (they add up to " +
                            formatNumber(sum) + " m" + (last ? "" : " before the last") + ")");
    }
    p.sections.push_back(s);
  }
}

/// `attachments:` point loads by arc length from the base of the configured cable.
void parseAttachments(const YAML::Node& rows, CableParams& p) {
  const std::string key = "attachments";
  if (!rows.IsSequence()) {
    throw ConfigError(key, describeNode(rows), "a list of {arc_length: m, mass: kg, volume: m^3, drag_area: m^2, added_mass: kg}");
  }
  const double total = p.totalLength();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Section row(rows[i], key + "[" + std::to_string(i) + "]");
    AttachmentParams a;
    a.arc_length = row.number("arc_length", 0.0, 0.0, total, false, "m", true);
    a.mass = row.number("mass", 0.0, 0.0, 1e7, false, "kg");
    a.volume = row.number("volume", 0.0, 0.0, 1e4, false, "m^3");
    a.drag_area = row.number("drag_area", 0.0, 0.0, 1e4, false, "m^2");
    a.added_mass = row.number("added_mass", 0.0, 0.0, 1e7, false, "kg");
    row.rejectUnknownKeys();
    p.attachments.push_back(a);
  }
}

/// `winch:` (after everything else: it counts the drum's slots the model will put in front of the
/// configured cable, ChainModel::withDrumSlots).
void parseWinch(Section winch, CableParams& p) {
  WinchParams& w = p.winch;
  const double deployed = p.totalLength();
  const double link = p.link_lengths.front();
  w.enabled = true;
  w.link_length = link;
  w.max_length = winch.number("max_length", 0.0, deployed, 1e5, false, "m", true);
  w.min_length = winch.number("min_length", link, link, deployed, false, "m");
  w.max_speed = winch.number("max_speed", 1.0, 0.0, 100.0, true, "m/s");
  w.max_acceleration = winch.number("max_acceleration", 0.5, 0.0, 1e3, true, "m/s^2");
  w.speed = winch.number("speed", 0.0, -w.max_speed, w.max_speed, false, "m/s");
  if (winch.has("schedule")) {
    const YAML::Node rows = winch.raw("schedule");
    const std::string key = winch.path() + ".schedule";
    if (!rows.IsSequence()) {
      throw ConfigError(key, describeNode(rows), "a list of {time: s, speed: m/s} or {time: s, length: m}");
    }
    double previous = -kInf;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Section row(rows[i], key + "[" + std::to_string(i) + "]");
      WinchCommand c;
      c.time = row.number("time", 0.0, 0.0, 1e7, false, "s", true);
      if (!(c.time > previous)) throw ConfigError(row.path() + ".time", describeNode(rows[i]["time"]), "times strictly increasing");
      previous = c.time;
      const bool has_speed = row.has("speed"), has_length = row.has("length");
      if (has_speed == has_length) {
        throw ConfigError(row.path(), describeNode(rows[i]), "exactly one of speed [m/s] or length [m]");
      }
      c.to_length = has_length;
      c.value = has_length ? row.number("length", 0.0, w.min_length, w.max_length, false, "m")
                           : row.number("speed", 0.0, -w.max_speed, w.max_speed, false, "m/s");
      row.rejectUnknownKeys();
      w.schedule.push_back(c);
    }
  }
  winch.rejectUnknownKeys();
  // Slots for the longest deployment: one more than the whole links it adds, since the winch's link
  // is between one and 2.25 links long.
  const int stored = static_cast<int>(std::ceil((w.max_length - deployed) / link - 1e-9)) + 1;
  if (p.links + stored > kMaxLinks) {
    throw ConfigError(winch.path() + ".max_length", formatNumber(w.max_length),
                      "at most " + std::to_string(kMaxLinks) + " links of " + std::to_string(link) + " m in all");
  }
  w.stored_links = stored;
}

}  // namespace

CableParams parseConfig(const YAML::Node& root, const std::string& base_dir) {
  Section top(root, "");
  CableParams p;
  if (!top.has("cable")) throw ConfigError("cable", "(missing)", "a mapping with links, length, diameter, ...");
  CableRest cable_rest;
  parseCable(top.sub("cable"), p, cable_rest);
  parseLoad(top.sub("load"), p);
  Section base = top.sub("base");
  p.base.motion = parseMotion(base.sub("motion"));
  p.base.hang_off = vector3(base, "hang_off", 1e3, "m");
  p.base.fixity = base.choice("fixity", "clamped", {"clamped", "pinned"}) == "clamped" ? BaseFixity::kClamped
                                                                                       : BaseFixity::kPinned;
  if (base.has("direction")) {
    const std::vector<double> d = base.numberList("direction", 3, -1e3, 1e3, false, "");
    p.base.direction = Eigen::Vector3d(d[0], d[1], d[2]);
    if (p.base.direction.norm() < 1e-9) {
      throw ConfigError("base.direction", describeNode(base.raw("direction")), "a non-zero vector (world frame)");
    }
    p.base.direction.normalize();
  }
  base.rejectUnknownKeys();
  parseFluid(top.sub("fluid"), p);
  p.gravity = top.number("gravity", 9.81, 0.0, 100.0, false, "m/s^2");
  if (cable_rest.has_sections) parseSections(cable_rest.sections, cable_rest, p);
  if (top.has("attachments")) parseAttachments(top.raw("attachments"), p);
  if (top.has("seabed")) parseSeabed(top.sub("seabed"), base_dir, p);

  Section initial = top.sub("initial");
  p.initial.mode = initial.choice("mode", "angles", {"angles", "equilibrium"}) == "angles" ? InitialMode::kAngles
                                                                                       : InitialMode::kEquilibrium;
  p.initial.elevation = initial.perJoint("elevation", p.links, -M_PI, M_PI, "rad");
  p.initial.azimuth = initial.perJoint("azimuth", p.links, -M_PI, M_PI, "rad");
  p.initial.torsion = initial.perJoint("torsion", p.links, -1e3, 1e3, "rad");
  initial.rejectUnknownKeys();

  Section simulation = top.sub("simulation");
  p.simulation.dt = simulation.number("dt", 0.001, 0.0, 0.1, true, "s");
  const std::string integrator = simulation.choice("integrator", "rk4", {"rk4", "semi_implicit", "implicit"});
  p.simulation.integrator = integrator == "rk4"             ? Integrator::kRk4
                            : integrator == "semi_implicit" ? Integrator::kSemiImplicit
                                                            : Integrator::kImplicit;
  p.simulation.rho_infinity = simulation.number("rho_infinity", 0.9, 0.0, 1.0, false, "");
  p.simulation.duration = simulation.number("duration", 10.0, 0.0, 1e7, true, "s");
  p.simulation.formulation = simulation.choice("formulation", "recursive", {"paper", "recursive"}) == "recursive"
                                 ? Formulation::kRecursive
                                 : Formulation::kPaper;
  simulation.rejectUnknownKeys();
  if (top.has("winch")) parseWinch(top.sub("winch"), p);
  top.rejectUnknownKeys();
  checkConfigRules(p);  // the rules between keys (params/input_gate.h)
  return p;
}

void applyOverride(YAML::Node& root, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError(assignment, "(no '=')", "key.path=value, e.g. cable.links=10");
  }
  const std::string path = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw ConfigError(path, assignment.substr(eq + 1), std::string("a YAML value (") + e.what() + ")");
  }
  std::vector<std::string> parts;
  std::stringstream stream(path);
  for (std::string part; std::getline(stream, part, '.');) {
    if (part.empty()) throw ConfigError(path, assignment.substr(eq + 1), "a dotted key path without empty parts");
    parts.push_back(part);
  }
  // yaml-cpp nodes are handles: walk down with fresh handles (operator= on a handle would overwrite).
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node next = chain.back()[parts[i]];
    if (next.IsDefined() && !next.IsNull() && !next.IsMap()) {
      throw ConfigError(path, assignment.substr(eq + 1), "'" + parts[i] + "' to be a mapping");
    }
    chain.push_back(next);
  }
  chain.back()[parts.back()] = value;
}

namespace {
CableParams parseWithOverrides(YAML::Node root, const std::vector<std::string>& overrides, const std::string& base_dir) {
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const auto& o : overrides) applyOverride(root, o);
  return parseConfig(root, base_dir);
}
}  // namespace

CableParams loadConfigFile(const std::string& path, const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError("(file)", path, std::string("a readable YAML file: ") + e.what());
  }
  const std::size_t slash = path.find_last_of('/');
  return parseWithOverrides(root, overrides, slash == std::string::npos ? "" : path.substr(0, slash));
}

CableParams loadConfigString(const std::string& yaml_text, const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError("(text)", "", std::string("valid YAML: ") + e.what());
  }
  return parseWithOverrides(root, overrides, "");
}

}  // namespace cable_dynamics
