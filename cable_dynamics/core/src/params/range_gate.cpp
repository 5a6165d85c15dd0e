// checkConfigRanges (params/input_gate.h): a CableParams against the ranges the config loader reads its
// keys with (params/key_ranges.h), key by key, named as the loader names them.
#include <cmath>
#include <string>
#include <vector>

#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/params/key_ranges.h"

namespace cable_dynamics {
namespace {

std::string indexed(const std::string& key, std::size_t i) { return key + "[" + std::to_string(i) + "]"; }

void check(const std::string& key, double value, const NumberRange& range) {
  logCheckedKey(key);
  if (!range.allows(value)) throw ConfigError(key, formatNumber(value), range.text());
}

void check(const std::string& key, int value, const IntegerRange& range) {
  logCheckedKey(key);
  if (!range.allows(value)) throw ConfigError(key, std::to_string(value), range.text());
}

/// Every coefficient of a vector or matrix (a matrix row by row, as a config lists it): `key[i]`.
template <class Values>
void checkEach(const std::string& key, const Values& values, const NumberRange& range) {
  logCheckedKey(key);
  for (Eigen::Index r = 0; r < values.rows(); ++r) {
    for (Eigen::Index c = 0; c < values.cols(); ++c) {
      const double v = values(r, c);
      if (!range.allows(v)) throw ConfigError(indexed(key, r * values.cols() + c), formatNumber(v), range.text());
    }
  }
}

/// One value per configured link: `values` has `links` entries, the first `slots` of them a winch's
/// drum slots (not configured, not checked); the others are named from 0, as the config lists them.
void checkPerLink(const std::string& key, const std::vector<double>& values, int links, int slots,
                  const NumberRange& range) {
  logCheckedKey(key);
  if (static_cast<int>(values.size()) != links) {
    throw ConfigError(key, std::to_string(values.size()) + " values",
                      "one per link: " + std::to_string(links) + (slots > 0 ? " (with the drum's slots)" : ""));
  }
  for (int k = slots; k < links; ++k) {
    if (!range.allows(values[k])) throw ConfigError(indexed(key, k - slots), formatNumber(values[k]), range.text());
  }
}

void checkUnit(const std::string& key, const Eigen::Vector3d& direction) {
  checkEach(key, direction, ranges::kDirection);
  if (!(std::abs(direction.norm() - 1.0) <= 1e-9)) {
    throw ConfigError(key, formatVector(direction), "a unit vector (the config loader normalizes a config's)");
  }
}

void checkMotion(const std::string& at, const MotionParams& m) {
  checkEach(at + ".offset", m.offset, ranges::kMotionOffset);
  checkEach(at + ".amplitude", m.amplitude, ranges::kMotionAmplitude);
  check(at + ".period", m.period, ranges::kMotionPeriod);
  check(at + ".phase", m.phase, ranges::kPhase);
  checkEach(at + ".velocity", m.velocity, ranges::kMotionVelocity);
  checkEach(at + ".attitude_amplitude", m.attitude_amplitude, ranges::kAttitudeAngle);
  checkEach(at + ".attitude_phase", m.attitude_phase, ranges::kPhase);
}

void checkSections(const CableParams& p) {
  const double total = p.deployedLength();
  double sum = 0.0;
  for (std::size_t i = 0; i < p.sections.size(); ++i) {
    const SectionParams& s = p.sections[i];
    const std::string at = indexed("cable.sections", i);
    check(at + ".length", s.length, ranges::kLength);
    check(at + ".diameter", s.diameter, ranges::kDiameter);
    check(at + ".mass_per_length", s.mass_per_length, ranges::kMassPerLength);
    check(at + ".bending_rigidity", s.bending_rigidity, ranges::kRigidity);
    check(at + ".torsional_rigidity", s.torsional_rigidity, ranges::kRigidity);
    check(at + ".axial_stiffness", s.axial_stiffness, ranges::kAxialStiffness);
    check(at + ".drag_normal", s.drag_normal, ranges::kCoefficient);
    check(at + ".drag_tangential", s.drag_tangential, ranges::kCoefficient);
    check(at + ".added_mass", s.added_mass, ranges::kCoefficient);
    if (s.min_bend_radius != 0.0) check(at + ".limits.min_bend_radius", s.min_bend_radius, ranges::kBendRadius);
    sum += s.length;
  }
  if (!p.sections.empty() && std::abs(sum - total) > 1e-9 * total) {
    throw ConfigError("cable.sections", std::to_string(p.sections.size()) + " sections of " + formatNumber(sum) + " m",
                      "section lengths adding up to the cable's length " + formatNumber(total) + " m");
  }
}

void checkCable(const CableParams& p) {
  const int slots = p.drumSlots();
  check("cable.links", p.links - slots, ranges::kLinks);
  checkPerLink("cable.link_lengths", p.link_lengths, p.links, slots, ranges::kLength);
  check("cable.length", p.deployedLength(), ranges::kLength);
  check("cable.diameter", p.diameter, ranges::kDiameter);
  check("cable.mass_per_length", p.mass_per_length, ranges::kMassPerLength);
  check("cable.axial_stiffness", p.axial_stiffness, ranges::kAxialStiffness);
  check("cable.axial_damping", p.axial_damping, ranges::kAxialDamping);
  // An absent limit is 0 (LimitParams).
  const LimitParams& l = p.limits;
  if (l.max_tension != 0.0) check("cable.limits.max_tension", l.max_tension, ranges::kMaxTension);
  if (l.min_bend_radius != 0.0) check("cable.limits.min_bend_radius", l.min_bend_radius, ranges::kBendRadius);
  if (l.has_min_seabed_clearance) {
    check("cable.limits.min_seabed_clearance", l.min_seabed_clearance, ranges::kSeabedClearance);
  }
  const StiffnessParams& k = p.stiffness;
  check("cable.stiffness.elevation", k.elevation, ranges::kJointStiffness);
  check("cable.stiffness.azimuth", k.azimuth, ranges::kJointStiffness);
  check("cable.stiffness.torsion", k.torsion, ranges::kJointStiffness);
  check("cable.stiffness.bending_rigidity", k.bending_rigidity, ranges::kRigidity);
  check("cable.stiffness.torsional_rigidity", k.torsional_rigidity, ranges::kRigidity);
  check("cable.damping.elevation", p.damping.elevation, ranges::kJointDamping);
  check("cable.damping.azimuth", p.damping.azimuth, ranges::kJointDamping);
  check("cable.damping.torsion", p.damping.torsion, ranges::kJointDamping);
  checkSections(p);
}

void checkBody(const RovBodyParams& b) {
  checkEach("load.body.inertia", b.inertia, ranges::kInertia);
  checkEach("load.body.added_mass", b.added_mass, ranges::kBodyAddedMass);
  checkEach("load.body.linear_damping", b.linear_damping, ranges::kLinearDamping);
  checkEach("load.body.quadratic_damping", b.quadratic_damping, ranges::kQuadraticDamping);
  checkEach("load.body.center_of_gravity", b.center_of_gravity, ranges::kBodyCentre);
  checkEach("load.body.center_of_buoyancy", b.center_of_buoyancy, ranges::kBodyCentre);
  checkEach("load.body.initial_attitude", b.initial_attitude, ranges::kAttitudeAngle);
  checkEach("load.body.station_keeping.position_gain", b.position_gain, ranges::kPositionGain);
  checkEach("load.body.station_keeping.velocity_gain", b.velocity_gain, ranges::kVelocityGain);
  checkEach("load.body.station_keeping.integral_gain", b.integral_gain, ranges::kIntegralGain);
  checkEach("load.body.station_keeping.attitude_gain", b.attitude_gain, ranges::kAttitudeGain);
  checkEach("load.body.station_keeping.rate_gain", b.rate_gain, ranges::kRateGain);
  check("load.body.station_keeping.max_force", b.max_force, ranges::kMaxForce);
  check("load.body.station_keeping.max_torque", b.max_torque, ranges::kMaxTorque);
}

void checkEnds(const CableParams& p) {
  const LoadParams& load = p.load;
  check("load.mass", load.mass, ranges::kMass);
  check("load.volume", load.volume, ranges::kVolume);
  check("load.drag_area", load.drag_area, ranges::kDragArea);
  check("load.added_mass", load.added_mass, ranges::kAddedMass);
  check("load.coupling.stiffness", load.coupling_stiffness, ranges::kCouplingStiffness);
  check("load.coupling.damping", load.coupling_damping, ranges::kCouplingDamping);
  check("load.coupling.integral_time", load.coupling_integral_time, ranges::kCouplingIntegralTime);
  checkMotion("load.motion", load.motion);
  checkEach("load.attachment", load.attachment, ranges::kBodyPoint);
  checkUnit("load.direction", load.direction);
  checkBody(load.body);
  checkMotion("base.motion", p.base.motion);
  checkEach("base.hang_off", p.base.hang_off, ranges::kBodyPoint);
  checkUnit("base.direction", p.base.direction);
}

void checkFluid(const CableParams& p) {
  const FluidParams& f = p.fluid;
  check("fluid.density", f.density, ranges::kFluidDensity);
  check("fluid.drag_normal", f.drag_normal, ranges::kCoefficient);
  check("fluid.drag_tangential", f.drag_tangential, ranges::kCoefficient);
  check("fluid.added_mass", f.added_mass, ranges::kCoefficient);
  checkEach("fluid.current", f.current, ranges::kCurrent);
  check("fluid.drag_points", f.drag_points, ranges::kDragPoints);
  logCheckedKey("fluid.current_profile");
  for (std::size_t i = 0; i < f.current_profile.size(); ++i) {
    for (int j = 0; j < 4; ++j) {  // depth, current x, y, z
      if (!ranges::kProfileRow.allows(f.current_profile[i](j))) {
        throw ConfigError(indexed(indexed("fluid.current_profile", i), j), formatNumber(f.current_profile[i](j)),
                          ranges::kProfileRow.text());
      }
    }
    if (i > 0 && !(f.current_profile[i](0) > f.current_profile[i - 1](0))) {
      throw ConfigError(indexed("fluid.current_profile", i), formatVector(f.current_profile[i]), "depths strictly increasing");
    }
  }
  if (!f.current_profile.empty() && !f.current.isZero()) {
    throw ConfigError("fluid.current", formatVector(f.current), "[0, 0, 0] when current_profile is given (one or the other)");
  }
  check("gravity", p.gravity, ranges::kGravity);
}

void checkSeabed(const SeabedParams& s) {
  if (!s.enabled) return;
  if (s.has_grid) {
    const SeabedGrid& g = s.grid;
    checkEach("seabed.grid.origin", g.origin, ranges::kGridOrigin);
    checkEach("seabed.grid.spacing", g.spacing, ranges::kGridSpacing);
    if (g.depth.rows() < 2 || g.depth.cols() < 2) {
      throw ConfigError("seabed.grid.depth", std::to_string(g.depth.rows()) + " x " + std::to_string(g.depth.cols()),
                        "at least 2 x 2 depths");
    }
    logCheckedKey("seabed.grid.depth");
    for (Eigen::Index j = 0; j < g.depth.rows(); ++j) {
      for (Eigen::Index i = 0; i < g.depth.cols(); ++i) {
        if (!ranges::kGridDepth.allows(g.depth(j, i))) {
          throw ConfigError(indexed(indexed("seabed.grid.depth", j), i), formatNumber(g.depth(j, i)), ranges::kGridDepth.text());
        }
      }
    }
  } else {
    check("seabed.depth", s.depth, ranges::kSeabedDepth);
  }
  check("seabed.penetration", s.penetration, ranges::kPenetration);
  check("seabed.stiffness", s.stiffness, ranges::kSeabedStiffness);
  check("seabed.damping_ratio", s.damping_ratio, ranges::kDampingRatio);
  check("seabed.friction.axial", s.friction_axial, ranges::kFriction);
  check("seabed.friction.lateral", s.friction_lateral, ranges::kFriction);
  check("seabed.friction.velocity", s.friction_velocity, ranges::kFrictionVelocity);
  check("seabed.friction.breakout", s.friction_breakout, ranges::kFrictionBreakout);
  check("seabed.contact_points", s.contact_points, ranges::kContactPoints);
}

void checkWinch(const CableParams& p) {
  const WinchParams& w = p.winch;
  if (!w.enabled) return;
  const double deployed = p.deployedLength();
  const double link = p.link_lengths[p.drumSlots()];  // the configured base link (a size checked before)
  if (w.link_length != link) {
    throw ConfigError("winch.link_length", formatNumber(w.link_length),
                      formatNumber(link) + " m, the configured base link's length (the config loader sets it)");
  }
  check("winch.max_length", w.max_length, ranges::winchMaxLength(deployed));
  check("winch.min_length", w.min_length, ranges::winchMinLength(link, deployed));
  check("winch.max_speed", w.max_speed, ranges::kWinchMaxSpeed);
  check("winch.max_acceleration", w.max_acceleration, ranges::kWinchMaxAcceleration);
  check("winch.speed", w.speed, ranges::winchSpeed(w.max_speed));
  double previous = -ranges::kInf;
  for (std::size_t i = 0; i < w.schedule.size(); ++i) {
    const WinchCommand& c = w.schedule[i];
    const std::string at = indexed("winch.schedule", i);
    check(at + ".time", c.time, ranges::kScheduleTime);
    if (!(c.time > previous)) throw ConfigError(at + ".time", formatNumber(c.time), "times strictly increasing");
    previous = c.time;
    if (c.to_length) {
      check(at + ".length", c.value, ranges::winchLength(w.min_length, w.max_length));
    } else {
      check(at + ".speed", c.value, ranges::winchSpeed(w.max_speed));
    }
  }
  const int stored = drumSlotsFor(w, deployed);
  if (w.stored_links != stored) {
    throw ConfigError("winch.stored_links", std::to_string(w.stored_links),
                      std::to_string(stored) + ", the drum's slots for winch.max_length (the config loader counts them)");
  }
  if (p.links - p.drumSlots() + stored > ranges::kLinks.hi) {
    throw ConfigError("winch.max_length", formatNumber(w.max_length),
                      "at most " + std::to_string(ranges::kLinks.hi) + " links of " + formatNumber(link) + " m in all");
  }
}

void checkAttachments(const CableParams& p) {
  const double total = p.deployedLength();
  for (std::size_t i = 0; i < p.attachments.size(); ++i) {
    const AttachmentParams& a = p.attachments[i];
    const std::string at = indexed("attachments", i);
    check(at + ".arc_length", a.arc_length, ranges::arcLength(total));
    check(at + ".mass", a.mass, ranges::kMass);
    check(at + ".volume", a.volume, ranges::kVolume);
    check(at + ".drag_area", a.drag_area, ranges::kDragArea);
    check(at + ".added_mass", a.added_mass, ranges::kAddedMass);
  }
}

void checkStart(const CableParams& p) {
  const int slots = p.drumSlots();
  checkPerLink("initial.elevation", p.initial.elevation, p.links, slots, ranges::kInitialAngle);
  checkPerLink("initial.azimuth", p.initial.azimuth, p.links, slots, ranges::kInitialAngle);
  checkPerLink("initial.torsion", p.initial.torsion, p.links, slots, ranges::kInitialTorsion);
  check("simulation.dt", p.simulation.dt, ranges::kDt);
  check("simulation.rho_infinity", p.simulation.rho_infinity, ranges::kRhoInfinity);
  check("simulation.duration", p.simulation.duration, ranges::kDuration);
}

}  // namespace

void checkConfigRanges(const CableParams& p) {
  // The cable first: the sizes and lengths the others are measured against.
  checkCable(p);
  checkEnds(p);
  checkFluid(p);
  checkSeabed(p.seabed);
  checkWinch(p);
  checkAttachments(p);
  checkStart(p);
}

}  // namespace cable_dynamics
