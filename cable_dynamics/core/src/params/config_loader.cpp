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

constexpr double kInf = std::numeric_limits<double>::infinity();

/// What parseCable leaves for later: the sections' defaults need the fluid's coefficients.
struct CableRest {
  bool has_sections = false;
  YAML::Node sections;            ///< cable.sections when has_sections
  double material_density = 0.0;  ///< [kg/m^3] when the cable is given by material_density
};

void parseCable(Section cable, CableParams& p, CableRest& rest) {
  p.links = cable.integer("links", 1, ranges::kLinks, true);
  if (cable.has("link_lengths")) {
    // The list overrides `length`: the total length is then the sum of the list.
    p.link_lengths = cable.numberList("link_lengths", p.links, ranges::kLength);
    cable.number("length", 0.0, ranges::kLength);  // still validated when present
  } else {
    const double total = cable.number("length", 0.0, ranges::kLength, true);
    p.link_lengths.assign(p.links, total / p.links);
  }
  p.diameter = cable.number("diameter", 0.0, ranges::kDiameter, true);
  const bool has_linear_density = cable.has("mass_per_length");
  const bool has_material_density = cable.has("material_density");
  if (has_linear_density == has_material_density) {
    throw ConfigError(cable.path() + ".mass_per_length", has_linear_density ? "given with material_density" : "(missing)",
                      "exactly one of cable.mass_per_length [kg/m] or cable.material_density [kg/m^3]");
  }
  if (has_linear_density) {
    p.mass_per_length = cable.number("mass_per_length", 0.0, ranges::kMassPerLength);
  } else {
    const double rho = cable.number("material_density", 0.0, ranges::kMaterialDensity);
    p.mass_per_length = rho * M_PI * 0.25 * p.diameter * p.diameter;
    rest.material_density = rho;
  }
  p.axial_stiffness = cable.number("axial_stiffness", 0.0, ranges::kAxialStiffness);
  p.axial_damping = cable.number("axial_damping", 0.0, ranges::kAxialDamping);
  {
    // Each limit, when given, must be positive (the clearance may be 0); absent: no limit.
    Section limits = cable.sub("limits");
    LimitParams& l = p.limits;
    if (limits.has("max_tension")) l.max_tension = limits.number("max_tension", 0.0, ranges::kMaxTension);
    if (limits.has("min_bend_radius")) l.min_bend_radius = limits.number("min_bend_radius", 0.0, ranges::kBendRadius);
    l.has_min_seabed_clearance = limits.has("min_seabed_clearance");
    if (l.has_min_seabed_clearance) {
      l.min_seabed_clearance = limits.number("min_seabed_clearance", 0.0, ranges::kSeabedClearance);
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
  p.stiffness.elevation = stiffness.number("elevation", 0.0, ranges::kJointStiffness);
  p.stiffness.azimuth = stiffness.number("azimuth", 0.0, ranges::kJointStiffness);
  p.stiffness.torsion = stiffness.number("torsion", 0.0, ranges::kJointStiffness);
  p.stiffness.bending_rigidity = stiffness.number("bending_rigidity", 0.0, ranges::kRigidity);
  p.stiffness.torsional_rigidity = stiffness.number("torsional_rigidity", 0.0, ranges::kRigidity);
  stiffness.rejectUnknownKeys();

  Section damping = cable.sub("damping");
  p.damping.elevation = damping.number("elevation", 0.0, ranges::kJointDamping);
  p.damping.azimuth = damping.number("azimuth", 0.0, ranges::kJointDamping);
  p.damping.torsion = damping.number("torsion", 0.0, ranges::kJointDamping);
  damping.rejectUnknownKeys();
  cable.rejectUnknownKeys();
}

Eigen::Vector3d vector3(Section& s, const std::string& key, const NumberRange& range) {
  if (!s.has(key)) return Eigen::Vector3d::Zero();
  const std::vector<double> v = s.numberList(key, 3, range);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

MotionParams parseMotion(Section motion) {
  MotionParams m;
  m.offset = vector3(motion, "offset", ranges::kMotionOffset);
  m.amplitude = vector3(motion, "amplitude", ranges::kMotionAmplitude);
  m.period = motion.number("period", 10.0, ranges::kMotionPeriod);
  m.phase = motion.number("phase", 0.0, ranges::kPhase);
  m.velocity = vector3(motion, "velocity", ranges::kMotionVelocity);
  m.attitude_amplitude = vector3(motion, "attitude_amplitude", ranges::kAttitudeAngle);
  m.attitude_phase = vector3(motion, "attitude_phase", ranges::kPhase);
  motion.rejectUnknownKeys();
  return m;
}

/// A square matrix given whole (size^2 numbers, row by row) or by its diagonal (size numbers); `fallback`
/// when absent.
template <int Size>
Eigen::Matrix<double, Size, Size> squareMatrix(Section& s, const std::string& key, const NumberRange& range,
                                               const Eigen::Matrix<double, Size, Size>& fallback) {
  if (!s.has(key)) return fallback;
  Eigen::Matrix<double, Size, Size> m = Eigen::Matrix<double, Size, Size>::Zero();
  const bool whole = s.raw(key).IsSequence() && s.raw(key).size() == static_cast<std::size_t>(Size * Size);
  const std::vector<double> v = s.numberList(key, whole ? Size * Size : Size, range);
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
  b.inertia = squareMatrix<3>(body, "inertia", ranges::kInertia, b.inertia);
  b.added_mass = squareMatrix<6>(body, "added_mass", ranges::kBodyAddedMass, b.added_mass);
  const auto six = [&body](const char* key, const NumberRange& range) {
    Eigen::Matrix<double, 6, 1> v = Eigen::Matrix<double, 6, 1>::Zero();
    if (!body.has(key)) return v;
    const std::vector<double> list = body.numberList(key, 6, range);
    for (int i = 0; i < 6; ++i) v(i) = list[i];
    return v;
  };
  b.linear_damping = six("linear_damping", ranges::kLinearDamping);
  b.quadratic_damping = six("quadratic_damping", ranges::kQuadraticDamping);
  b.center_of_gravity = vector3(body, "center_of_gravity", ranges::kBodyCentre);
  b.center_of_buoyancy = vector3(body, "center_of_buoyancy", ranges::kBodyCentre);
  b.initial_attitude = vector3(body, "initial_attitude", ranges::kAttitudeAngle);
  Section keeper = body.sub("station_keeping");
  const auto gains = [&keeper](const char* key, const NumberRange& range) {
    if (!keeper.has(key)) return Eigen::Vector3d::Zero().eval();
    const std::vector<double> v = keeper.numberList(key, 3, range);
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  b.position_gain = gains("position_gain", ranges::kPositionGain);
  b.velocity_gain = gains("velocity_gain", ranges::kVelocityGain);
  b.integral_gain = gains("integral_gain", ranges::kIntegralGain);
  b.attitude_gain = gains("attitude_gain", ranges::kAttitudeGain);
  b.rate_gain = gains("rate_gain", ranges::kRateGain);
  b.max_force = keeper.number("max_force", 1e300, ranges::kMaxForce);
  b.max_torque = keeper.number("max_torque", 1e300, ranges::kMaxTorque);
  keeper.rejectUnknownKeys();
  body.rejectUnknownKeys();
  return b;
}

void parseLoad(Section load, CableParams& p) {
  p.load.mass = load.number("mass", 0.0, ranges::kMass);
  p.load.volume = load.number("volume", 0.0, ranges::kVolume);
  const std::string mode = load.choice("mode", "free", {"free", "anchored", "attached", "body"});
  p.load.mode = mode == "free"       ? LoadMode::kFree
                : mode == "anchored" ? LoadMode::kAnchored
                : mode == "attached" ? LoadMode::kAttached
                                     : LoadMode::kBody;
  if (load.has("body")) p.load.body = parseRovBody(load.sub("body"));
  p.load.drag_area = load.number("drag_area", 0.0, ranges::kDragArea);
  p.load.added_mass = load.number("added_mass", 0.0, ranges::kAddedMass);
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
  p.load.coupling_stiffness = coupling.number("stiffness", 2.0e4, ranges::kCouplingStiffness);
  p.load.coupling_damping = coupling.number("damping", 2.0e3, ranges::kCouplingDamping);
  p.load.coupling_integral_time = coupling.number("integral_time", 0.0, ranges::kCouplingIntegralTime);
  coupling.rejectUnknownKeys();
  p.load.motion = parseMotion(load.sub("motion"));
  p.load.attachment = vector3(load, "attachment", ranges::kBodyPoint);
  p.load.fixity = load.choice("fixity", "pinned", {"pinned", "clamped"}) == "pinned" ? TipFixity::kPinned : TipFixity::kClamped;
  if (load.has("direction")) {
    const std::vector<double> d = load.numberList("direction", 3, ranges::kDirection);
    p.load.direction = Eigen::Vector3d(d[0], d[1], d[2]);
    if (p.load.direction.norm() < 1e-9) {
      throw ConfigError("load.direction", describeNode(load.raw("direction")), "a non-zero vector");
    }
    p.load.direction.normalize();
  }
  load.rejectUnknownKeys();
}

void parseFluid(Section fluid, CableParams& p) {
  p.fluid.density = fluid.number("density", 1025.0, ranges::kFluidDensity);
  p.fluid.drag_normal = fluid.number("drag_normal", 1.2, ranges::kCoefficient);
  p.fluid.drag_tangential = fluid.number("drag_tangential", 0.01, ranges::kCoefficient);
  p.fluid.added_mass = fluid.number("added_mass", 1.0, ranges::kCoefficient);
  p.fluid.current = vector3(fluid, "current", ranges::kCurrent);  // the setter's range too
  p.fluid.drag_points = fluid.integer("drag_points", 3, ranges::kDragPoints);
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
      const std::vector<double> v = row.numberList("row", 4, ranges::kProfileRow);
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
    s.length = row.number("length", 0.0, ranges::kLength, !last);
    s.diameter = row.number("diameter", p.diameter, ranges::kDiameter);
    const bool linear = row.has("mass_per_length"), material = row.has("material_density");
    if (linear && material) {
      throw ConfigError(row.path() + ".mass_per_length", "given with material_density",
                        "at most one of mass_per_length [kg/m] or material_density [kg/m^3]");
    }
    if (linear) {
      s.mass_per_length = row.number("mass_per_length", 0.0, ranges::kMassPerLength);
    } else {
      // Left out: the cable's material density over this diameter, or the cable's mass per length.
      const double rho = material ? row.number("material_density", 0.0, ranges::kMaterialDensity) : rest.material_density;
      s.mass_per_length = rho > 0.0 ? rho * M_PI * 0.25 * s.diameter * s.diameter : p.mass_per_length;
    }
    s.bending_rigidity = row.number("bending_rigidity", k.bending_rigidity, ranges::kRigidity);
    s.torsional_rigidity = row.number("torsional_rigidity", k.torsional_rigidity, ranges::kRigidity);
    if (row.has("bending_rigidity") && s.bending_rigidity > 0.0 && (k.elevation > 0.0 || k.azimuth > 0.0)) {
      throw ConfigError(row.path() + ".bending_rigidity", formatNumber(s.bending_rigidity),
                        "0 when cable.stiffness.elevation or azimuth is given (one or the other)");
    }
    if (row.has("torsional_rigidity") && s.torsional_rigidity > 0.0 && k.torsion > 0.0) {
      throw ConfigError(row.path() + ".torsional_rigidity", formatNumber(s.torsional_rigidity),
                        "0 when cable.stiffness.torsion is given (one or the other)");
    }
    s.axial_stiffness = row.number("axial_stiffness", p.axial_stiffness, ranges::kAxialStiffness);
    s.drag_normal = row.number("drag_normal", p.fluid.drag_normal, ranges::kCoefficient);
    s.drag_tangential = row.number("drag_tangential", p.fluid.drag_tangential, ranges::kCoefficient);
    s.added_mass = row.number("added_mass", p.fluid.added_mass, ranges::kCoefficient);
    s.min_bend_radius = p.limits.min_bend_radius;  // the cable's unless the section has its own
    {
      Section limits = row.sub("limits");
      if (limits.has("min_bend_radius")) s.min_bend_radius = limits.number("min_bend_radius", 0.0, ranges::kBendRadius);
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
    a.arc_length = row.number("arc_length", 0.0, ranges::arcLength(total), true);
    a.mass = row.number("mass", 0.0, ranges::kMass);
    a.volume = row.number("volume", 0.0, ranges::kVolume);
    a.drag_area = row.number("drag_area", 0.0, ranges::kDragArea);
    a.added_mass = row.number("added_mass", 0.0, ranges::kAddedMass);
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
  w.max_length = winch.number("max_length", 0.0, ranges::winchMaxLength(deployed), true);
  w.min_length = winch.number("min_length", link, ranges::winchMinLength(link, deployed));
  w.max_speed = winch.number("max_speed", 1.0, ranges::kWinchMaxSpeed);
  w.max_acceleration = winch.number("max_acceleration", 0.5, ranges::kWinchMaxAcceleration);
  w.speed = winch.number("speed", 0.0, ranges::winchSpeed(w.max_speed));
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
      c.time = row.number("time", 0.0, ranges::kScheduleTime, true);
      if (!(c.time > previous)) throw ConfigError(row.path() + ".time", describeNode(rows[i]["time"]), "times strictly increasing");
      previous = c.time;
      const bool has_speed = row.has("speed"), has_length = row.has("length");
      if (has_speed == has_length) {
        throw ConfigError(row.path(), describeNode(rows[i]), "exactly one of speed [m/s] or length [m]");
      }
      c.to_length = has_length;
      c.value = has_length ? row.number("length", 0.0, ranges::winchLength(w.min_length, w.max_length))
                           : row.number("speed", 0.0, ranges::winchSpeed(w.max_speed));
      row.rejectUnknownKeys();
      w.schedule.push_back(c);
    }
  }
  winch.rejectUnknownKeys();
  w.stored_links = drumSlotsFor(w, deployed);  // at most kLinks in all: the gate's (checkConfigRanges)
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
  p.base.hang_off = vector3(base, "hang_off", ranges::kBodyPoint);
  p.base.fixity = base.choice("fixity", "clamped", {"clamped", "pinned"}) == "clamped" ? BaseFixity::kClamped
                                                                                       : BaseFixity::kPinned;
  if (base.has("direction")) {
    const std::vector<double> d = base.numberList("direction", 3, ranges::kDirection);
    p.base.direction = Eigen::Vector3d(d[0], d[1], d[2]);
    if (p.base.direction.norm() < 1e-9) {
      throw ConfigError("base.direction", describeNode(base.raw("direction")), "a non-zero vector (world frame)");
    }
    p.base.direction.normalize();
  }
  base.rejectUnknownKeys();
  parseFluid(top.sub("fluid"), p);
  p.gravity = top.number("gravity", 9.81, ranges::kGravity);
  if (cable_rest.has_sections) parseSections(cable_rest.sections, cable_rest, p);
  if (top.has("attachments")) parseAttachments(top.raw("attachments"), p);
  if (top.has("seabed")) parseSeabed(top.sub("seabed"), base_dir, p);

  Section initial = top.sub("initial");
  p.initial.mode = initial.choice("mode", "angles", {"angles", "equilibrium"}) == "angles" ? InitialMode::kAngles
                                                                                       : InitialMode::kEquilibrium;
  p.initial.elevation = initial.perJoint("elevation", p.links, ranges::kInitialAngle);
  p.initial.azimuth = initial.perJoint("azimuth", p.links, ranges::kInitialAngle);
  p.initial.torsion = initial.perJoint("torsion", p.links, ranges::kInitialTorsion);
  initial.rejectUnknownKeys();

  Section simulation = top.sub("simulation");
  p.simulation.dt = simulation.number("dt", 0.001, ranges::kDt);
  const std::string integrator = simulation.choice("integrator", "rk4", {"rk4", "semi_implicit", "implicit"});
  p.simulation.integrator = integrator == "rk4"             ? Integrator::kRk4
                            : integrator == "semi_implicit" ? Integrator::kSemiImplicit
                                                            : Integrator::kImplicit;
  p.simulation.rho_infinity = simulation.number("rho_infinity", 0.9, ranges::kRhoInfinity);
  p.simulation.duration = simulation.number("duration", 10.0, ranges::kDuration);
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
