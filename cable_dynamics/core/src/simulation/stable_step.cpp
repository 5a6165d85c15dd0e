#include "cable_dynamics/simulation/stable_step.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "cable_dynamics/dynamics/seabed_contact.h"
#include "cable_dynamics/params/config_section.h"

namespace cable_dynamics {
namespace {

/// RK4's stability limit of h |lambda| on the imaginary axis (2 sqrt 2); 2.78 on the real axis is close.
constexpr double kRk4Reach = 2.8;
/// The recommended step keeps a factor 2 from the limit.
constexpr double kMargin = 2.0;

/// Keeps the largest rate seen and the mode it belongs to.
struct Stiffest {
  double rate = 0.0;
  std::string mode;
  void consider(double candidate, const std::string& name) {
    if (candidate > rate) {
      rate = candidate;
      mode = name;
    }
  }
};

/// The implicit integrator's step, for accuracy (StableStep::implicit_recommended). Continuum estimates
/// over the deployed cable of length L, mass and added mass per length mu, polar inertia per length i_p:
/// the first torsional mode of a rod fixed at the base, (pi / 2L) sqrt(GJ / i_p), and the third bending
/// mode as a taut string under the top tension T plus a cantilever, sqrt((3 pi / L)^2 T / mu +
/// (7.855 / L)^4 EI / mu) (for a hanging chain whose tension falls along it this is about twice the
/// frequency: on the safe side). GJ and EI from the joint springs, k s_k.
void recommendImplicitStep(const CableParams& params, const LinkProperties& p, double tension, StableStep& s) {
  constexpr double kAccuracy = 0.25, kCap = 0.01;
  double length = 0.0, mass = 0.0, polar = 0.0, torsion = 0.0, bending = 0.0;
  const int n = p.n;
  for (int k = 0; k < n; ++k) {
    const double l = p.length(k);
    if (l <= 0.0) continue;  // on a winch's drum
    const double arc = length > 0.0 ? 0.5 * (p.length(k - 1) + l) : 0.5 * l;  // the joint's spread (cable_params.cpp)
    length += l;
    mass += p.mass(k) + p.added_mass_per_length(k) * l;
    polar += p.inertia_polar(k);
    torsion = std::max(torsion, p.stiffness_torsion(k) * arc);
    bending = std::max(bending, std::max(p.stiffness_elevation(k), p.stiffness_azimuth(k)) * arc);
  }
  s.implicit_recommended = kCap;
  s.implicit_mode = "the 10 ms cap";
  if (length <= 0.0 || params.stiffness.model != StiffnessModel::kBending) return;
  const double mu = mass / length, ip = polar / length;
  const double torsional = ip > 0.0 ? M_PI / (2.0 * length) * std::sqrt(torsion / ip) : 0.0;
  const double third_bending = std::sqrt(std::pow(3.0 * M_PI / length, 2) * tension / mu +
                                         std::pow(7.855 / length, 4) * bending / mu);
  const double fastest = std::max(torsional, third_bending);
  if (kAccuracy / fastest < kCap) {
    s.implicit_recommended = kAccuracy / fastest;
    s.implicit_mode = torsional > third_bending ? "the first torsional mode" : "the third bending mode";
  }
}

}  // namespace

StableStep estimateStableStep(const CableParams& params, const LinkProperties& p) {
  Stiffest stiffest;
  const int n = p.n;
  // Hanging tension at the top: the submerged weight of everything below; with a winch, of the longest
  // deployment (its per-length weight from the tip link, which never leaves the water). With sections
  // and attachments, floats and heavy parts are counted by magnitude (a float does not lower the tension
  // a heavy part below it puts on the links above: a bound, never an underestimate of a hanging cable's).
  double submerged = p.submerged_mass.cwiseAbs().sum();
  for (const LinkAttachment& a : p.attachments) submerged += std::abs(a.submerged_mass);
  if (params.winch.enabled) {
    // The longest deployment at the heaviest per-length weight of its sections (no attachments with a winch).
    double per_length = 0.0;
    for (int k = 0; k < n; ++k) {
      if (p.length(k) > 0.0) per_length = std::max(per_length, std::abs(p.submerged_mass(k) / p.length(k)));
    }
    submerged = per_length * params.winch.max_length;
  }
  const double tension = p.gravity * (submerged + std::abs(p.load_submerged_mass));
  for (int k = 0; k < n; ++k) {
    const std::string joint = std::to_string(k + 1);
    // The link's own mass and added mass; its attachments only slow it down (left out: a bound).
    const double l = p.length(k), m = p.mass(k) + p.added_mass_per_length(k) * l;
    if (l <= 0.0) continue;  // on a winch's drum
    // Highest mode of a beaded string: 2 sqrt(T / (m l)) for links of mass m and length l.
    stiffest.consider(2.0 * std::sqrt(tension / (m * l)), "the string mode of link " + joint + " under the hanging tension");
    const double bend_inertia = p.mass(k) * l * l / 12.0;
    const double k_bend = std::max(p.stiffness_elevation(k), p.stiffness_azimuth(k));
    stiffest.consider(std::sqrt(4.0 * k_bend / bend_inertia), "the bend spring of joint " + joint);
    stiffest.consider(std::sqrt(4.0 * p.stiffness_torsion(k) / p.inertia_polar(k)), "the torsion spring of joint " + joint);
    const double c_bend = std::max(p.damping_elevation(k), p.damping_azimuth(k));
    stiffest.consider(4.0 * c_bend / bend_inertia, "the bend damper of joint " + joint);
    stiffest.consider(4.0 * p.damping_torsion(k) / p.inertia_polar(k), "the torsion damper of joint " + joint);
  }
  if (p.tip_clamp_stiffness > 0.0 && n > 0) {
    const double l = p.length(n - 1), bend_inertia = p.mass(n - 1) * l * l / 12.0;
    stiffest.consider(std::sqrt(4.0 * p.tip_clamp_stiffness / bend_inertia), "the tip clamp's bend spring");
    stiffest.consider(4.0 * p.tip_clamp_damping / bend_inertia, "the tip clamp's bend damper");
  }
  if (params.load.mode != LoadMode::kFree && n > 0) {
    const double l = p.length(n - 1);
    const double tip_mass = p.load_mass + params.load.added_mass + 0.5 * (p.mass(n - 1) + p.added_mass_per_length(n - 1) * l);
    stiffest.consider(std::sqrt(params.load.coupling_stiffness / tip_mass), "the load coupling's stiffness");
    stiffest.consider(params.load.coupling_damping / tip_mass, "the load coupling's damping");
  }
  if (params.seabed.enabled) {
    // The seabed's normal spring-damper on each link's mass per length, |lambda| = omega (zeta <= 1) or
    // omega (zeta + sqrt(zeta^2 - 1)); and the friction's viscous regime below the regularization speed,
    // mu w' / v_reg per unit mass, with w' the weight per length that presses the link down (its own).
    const SeabedContactConstants c = makeSeabedContact(params, p);
    const double zeta = params.seabed.damping_ratio, reach = zeta <= 1.0 ? 1.0 : zeta + std::sqrt(zeta * zeta - 1.0);
    for (int k = 0; k < n; ++k) {
      const double l = p.length(k);
      if (l <= 0.0) continue;
      const std::string link = std::to_string(k + 1);
      const double mass = p.mass(k) / l, across = mass + p.added_mass_per_length(k);
      stiffest.consider(reach * std::sqrt(c.stiffness / across), "the seabed's normal spring under link " + link);
      const double pressing = std::max(p.gravity * p.submerged_mass(k) / l, 0.0);
      stiffest.consider(c.friction_axial * pressing / (c.friction_velocity * mass), "the seabed's axial friction on link " + link);
      stiffest.consider(c.friction_lateral * pressing / (c.friction_velocity * across),
                        "the seabed's lateral friction on link " + link);
    }
  }
  StableStep s;
  s.rate = stiffest.rate;
  s.mode = stiffest.mode;
  const double infinity = std::numeric_limits<double>::infinity();
  s.limit = s.rate > 0.0 ? kRk4Reach / s.rate : infinity;
  s.recommended = s.rate > 0.0 ? kRk4Reach / (kMargin * s.rate) : infinity;
  recommendImplicitStep(params, p, tension, s);
  return s;
}

void requireStableTimeStep(const CableParams& params, const LinkProperties& properties) {
  if (params.simulation.integrator != Integrator::kRk4) return;
  const StableStep s = estimateStableStep(params, properties);
  if (params.simulation.dt <= s.limit) return;
  std::ostringstream expected;
  expected << "at most " << s.limit << " s for this cable with integrator rk4 (limited by " << s.mode
           << ", |lambda| = " << s.rate << " 1/s; recommended " << s.recommended
           << " s), or simulation.integrator: implicit (recommended dt " << s.implicit_recommended << " s)";
  std::ostringstream value;
  value << params.simulation.dt;
  throw ConfigError("simulation.dt", value.str(), expected.str());
}

}  // namespace cable_dynamics
