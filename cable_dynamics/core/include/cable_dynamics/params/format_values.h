#pragma once
/// \file
/// \brief A vector as refusal messages print it: "[x, y, z]" at full precision (17 digits), so that a value
///        near a bound never reads as the bound itself.

#include <sstream>
#include <string>

namespace cable_dynamics {

/// A number as refusal messages print it: the shortest of 15 or 17 significant digits that reads back as
/// the same double, so 19.999999999 never reads as 20 (std::to_string's 6 decimals did) and 0.1 stays 0.1.
inline std::string formatNumber(double v) {
  for (int digits : {15, 17}) {
    std::ostringstream s;
    s.precision(digits);
    s << v;
    if (digits == 17 || std::stod(s.str()) == v) return s.str();
  }
  return {};
}

template <class Vector>
std::string formatVector(const Vector& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for (int i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v(i);
  s << "]";
  return s.str();
}

}  // namespace cable_dynamics

namespace cable_dynamics {

/// A matrix row by row, "[[a, b], [c, d]]", each row as formatVector prints it.
template <class Matrix>
std::string formatMatrixRows(const Matrix& m) {
  std::string out = "[";
  for (int r = 0; r < m.rows(); ++r) out += (r ? ", " : "") + formatVector(m.row(r).transpose().eval());
  return out + "]";
}

}  // namespace cable_dynamics
