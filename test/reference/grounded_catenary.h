#pragma once
/// \file
/// \brief Irvine's elastic catenary with a grounded part: the truth test_axial_elasticity and the MoorDyn
///        bench (bench/moordyn/moordyn_grounded.cpp) hold the statics to. Written from the textbook's
///        equations, apart from the project's own catenary start (core/src/statics/catenary_start.cpp).

#include <cmath>
#include <string>
#include <vector>

namespace cable_reference {

/// The elastic catenary with a grounded part on a frictionless flat bed (Irvine, "Cable Structures", 1981,
/// ch. 2, with the anchor on the bed): a line of unstretched length L [m], submerged weight w [N/m] and EA
/// [N] from the anchor to a fairlead `span` out and `rise` up [m]. With H the horizontal tension and V the
/// fairlead's vertical tension [N] the suspended length is V / w, and
///   span = L - V / w + (H / w) asinh(V / H) + H L / EA,   rise = (H / w) (sqrt(1 + (V / H)^2) - 1) + V^2 / (2 w EA).
/// rise grows with V at a fixed H, span with H at the V that meets the rise: two nested bisections, to the
/// last digit.
struct GroundedCatenary {
  double horizontal = 0.0, vertical = 0.0;  // H, V [N]
};

inline GroundedCatenary groundedCatenary(double span, double rise, double length, double w, double ea) {
  auto vertical_for = [&](double h) {
    double lo = 0.0, hi = w * length;
    for (int i = 0; i < 200; ++i) {
      const double v = 0.5 * (lo + hi);
      const double z = h / w * (std::sqrt(1.0 + v * v / (h * h)) - 1.0) + v * v / (2.0 * w * ea);
      (z < rise ? lo : hi) = v;
    }
    return 0.5 * (lo + hi);
  };
  double lo = 1e-9 * w * length, hi = 100.0 * w * length;
  for (int i = 0; i < 200; ++i) {
    const double h = std::sqrt(lo * hi);  // bisection in log H
    const double v = vertical_for(h);
    const double x = length - v / w + h / w * std::asinh(v / h) + h * length / ea;
    (x < span ? lo : hi) = h;
  }
  GroundedCatenary out;
  out.horizontal = std::sqrt(lo * hi);
  out.vertical = vertical_for(out.horizontal);
  return out;
}

/// The grounded line of test_axial_elasticity (TheStaticsIsTheElasticCatenaryWithAGroundedPart), which
/// bench/moordyn/moordyn_grounded.cpp also gives MoorDyn: 100 m of 8 kg/m, 0.05 m, EA 2e5 N in water of
/// 1025 kg/m^3 (g = 9.81), from an anchor on a frictionless flat bed to a fairlead 20 m above it.
namespace grounded_line {
constexpr double kLength = 100.0, kRise = 20.0, kAxialStiffness = 2.0e5;   // m, m, N
constexpr double kMassPerLength = 8.0, kDiameter = 0.05;                    // kg/m, m
constexpr double kWaterDensity = 1025.0, kGravity = 9.81;                   // kg/m^3, m/s^2
/// The submerged weight w [N/m].
inline double weight() {
  return (kMassPerLength - kWaterDensity * M_PI * kDiameter * kDiameter / 4.0) * kGravity;
}
/// Its closed form at a horizontal span `span` [m].
inline GroundedCatenary closedForm(double span) {
  return groundedCatenary(span, kRise, kLength, weight(), kAxialStiffness);
}
/// The project's config of it (YAML) with link lengths `links` [m] (their sum is kLength) at `span` [m]: the
/// anchor exact, a 1 g point at the tip (a massless anchored tip locks the last link's stretch), the bed
/// 1e6 N/m^2 (it rests 59 um deep), the statics from the elastic catenary (initial.mode: equilibrium).
inline std::string projectConfig(const std::vector<double>& links, double span) {
  std::string lengths;
  for (double l : links) lengths += (lengths.empty() ? "" : ", ") + std::to_string(l);
  return "cable: {links: " + std::to_string(links.size()) + ", link_lengths: [" + lengths +
         "], diameter: " + std::to_string(kDiameter) + ", mass_per_length: " + std::to_string(kMassPerLength) +
         ", axial_stiffness: " + std::to_string(kAxialStiffness) + ", stiffness: {model: paper}}\n"
         // The anchor, as an offset from the tip hanging straight down kLength below the base: kRise below
         // the base (on the bed) and `span` out.
         "load: {mass: 0.001, mode: anchored, motion: {offset: [" + std::to_string(span) + ", 0.0, " +
         std::to_string(kLength - kRise) + "]}}\n"
         "fluid: {density: " + std::to_string(kWaterDensity) + ", drag_normal: 1.2, drag_tangential: 0.0, added_mass: 1.0}\n"
         "gravity: " + std::to_string(kGravity) + "\n"
         "seabed: {depth: " + std::to_string(kRise) + ", stiffness: 1.0e6, damping_ratio: 0.5}\n"
         "initial: {mode: equilibrium}\nsimulation: {integrator: implicit, dt: 0.01}\n";
}
}  // namespace grounded_line

}  // namespace cable_reference
