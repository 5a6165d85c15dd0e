#pragma once
/// \file
/// \brief Irvine's elastic catenary with a grounded part: the truth test_axial_elasticity and the MoorDyn
///        bench (bench/moordyn/moordyn_grounded.cpp) hold the statics to. Written from the textbook's
///        equations, apart from the project's own catenary start (core/src/statics/catenary_start.cpp).

#include <cmath>

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

}  // namespace cable_reference
