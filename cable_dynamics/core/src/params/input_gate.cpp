#include "cable_dynamics/params/input_gate.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "cable_dynamics/params/format_values.h"

namespace cable_dynamics {

const char* const kNoWinchMessage = "no winch is configured (config key winch:): the cable's length is fixed";

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// A refused input that is not a config key: "key = value: expected ...".
[[noreturn]] void refuse(const std::string& key, const std::string& value, const std::string& expected) {
  throw std::invalid_argument(key + " = " + value + ": expected " + expected);
}

/// A symmetric matrix that is positive definite (semi-definite when `semi`), or a ConfigError naming `key`.
template <typename Matrix>
void requireSymmetricDefinite(const Matrix& m, const std::string& key, bool semi) {
  const double scale = m.cwiseAbs().maxCoeff();
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(scale, 1e-300)) {
    throw ConfigError(key, formatMatrixRows(m), "a symmetric matrix");
  }
  // The signs of LDL^T's pivots are those of the eigenvalues (Sylvester's law of inertia).
  const double least = Eigen::LDLT<Matrix>(m).vectorD().minCoeff();
  if (semi ? least < -1e-9 * scale : !(least > 1e-12 * scale && scale > 0.0)) {
    throw ConfigError(key, formatMatrixRows(m),
                      std::string(semi ? "positive semi-definite" : "positive definite") + " (least LDL^T pivot " +
                          number(least) + ")");
  }
}

/// load.mode body: the ROV's mass, matrices and the integrators and ends that carry it (rov_body.h).
void checkRovBody(const CableParams& p) {
  const LoadParams& load = p.load;
  if (!(load.mass > 0.0)) throw ConfigError("load.mass", number(load.mass), "> 0 kg with load.mode: body");
  requireSymmetricDefinite(load.body.inertia, "load.body.inertia", false);
  requireSymmetricDefinite(load.body.added_mass, "load.body.added_mass", true);
  if (load.drag_area > 0.0 || load.added_mass > 0.0) {
    throw ConfigError(load.drag_area > 0.0 ? "load.drag_area" : "load.added_mass",
                      number(std::max(load.drag_area, load.added_mass)),
                      "0 with load.mode: body (the body's drag and added mass are load.body.*)");
  }
  if (load.fixity != TipFixity::kPinned) {
    throw ConfigError("load.fixity", "clamped", "pinned with load.mode: body (the tether hangs from a ball joint)");
  }
}

/// Axial elasticity (cable.axial_stiffness, docs/MODEL.md section 12): what carries it so far, and an EA
/// stiff enough for a cable (a stretch beyond 50 % under its own weight is no cable).
void checkAxialElasticity(const CableParams& p) {
  if (!p.stretches()) {
    if (p.axial_damping > 0.0) {
      throw ConfigError("cable.axial_damping", formatNumber(p.axial_damping), "0 without cable.axial_stiffness (rigid links)");
    }
    return;
  }
  for (std::size_t i = 0; i < p.sections.size(); ++i) {
    if (!(p.sections[i].axial_stiffness > 0.0)) {
      throw ConfigError("cable.sections[" + std::to_string(i) + "].axial_stiffness", "0 (and no cable.axial_stiffness)",
                        "> 0 N when another section stretches: give cable.axial_stiffness for the rest");
    }
  }
  if (p.simulation.formulation != Formulation::kRecursive) {
    throw ConfigError("simulation.formulation", "paper", "recursive with cable.axial_stiffness (the paper's model has rigid links)");
  }
  if (p.simulation.integrator == Integrator::kSemiImplicit) {
    throw ConfigError("simulation.integrator", integratorName(p.simulation.integrator),
                      "rk4 or implicit with cable.axial_stiffness (the semi-implicit step does not carry the stretch)");
  }
  // Under its own weight alone (the cable's submerged weight, or in air its weight; no load), the top of
  // a hanging cable carries W = sum w_k l_k: a strain W / EA above 0.5 is refused.
  const LinkProperties links = deriveLinkProperties(p);
  const double weight = p.gravity * links.submerged_mass.cwiseAbs().sum();
  const double least = links.axial_stiffness.minCoeff();
  if (least < 2.0 * weight) {
    throw ConfigError(p.sections.empty() ? "cable.axial_stiffness" : "cable.sections[" +
                          std::to_string(links.section(static_cast<int>(std::distance(
                              links.axial_stiffness.data(),
                              std::min_element(links.axial_stiffness.data(), links.axial_stiffness.data() + links.n))))) +
                          "].axial_stiffness",
                      formatNumber(least) + " N",
                      ">= " + formatNumber(2.0 * weight) +
                          " N: twice the cable's own weight, or it would stretch beyond 50 % under it");
  }
}

}  // namespace

void checkConfigRules(const CableParams& p) {
  checkConfigRanges(p);
  checkAxialElasticity(p);
  const StiffnessParams& k = p.stiffness;
  if (k.bending_rigidity > 0.0 && (k.elevation > 0.0 || k.azimuth > 0.0)) {
    throw ConfigError("cable.stiffness.bending_rigidity", std::to_string(k.bending_rigidity),
                      "0 when stiffness.elevation or stiffness.azimuth is given (one or the other)");
  }
  if (k.torsional_rigidity > 0.0 && k.torsion > 0.0) {
    throw ConfigError("cable.stiffness.torsional_rigidity", std::to_string(k.torsional_rigidity),
                      "0 when stiffness.torsion is given (one or the other)");
  }
  if (k.model == StiffnessModel::kBending && k.azimuth != k.elevation && k.azimuth != 0.0) {
    // One bending spring acts in every bending direction: a separate azimuth spring has no meaning there.
    throw ConfigError("cable.stiffness.azimuth", std::to_string(k.azimuth),
                      "0 or equal to stiffness.elevation with model: bending (the bend spring is elevation)");
  }
  if (p.load.mode == LoadMode::kBody) checkRovBody(p);
  if (p.load.heldExactly() && p.simulation.formulation != Formulation::kRecursive) {
    // The dense formulation has no constraint solve, and a hold stiff enough to be exact would limit its
    // RK4 to microseconds.
    throw ConfigError("simulation.formulation", "paper", "recursive with an exact anchor (or load.anchor: spring)");
  }
  if (p.limits.has_min_seabed_clearance && !p.seabed.enabled) {
    // A clearance is a height above the bottom: without a seabed there is nothing to measure it from.
    throw ConfigError("cable.limits.min_seabed_clearance", formatNumber(p.limits.min_seabed_clearance),
                      "absent without a seabed (give seabed.depth, seabed.grid or seabed.grid_file)");
  }
  if (p.load.fixity == TipFixity::kClamped && p.load.mode == LoadMode::kFree) {
    throw ConfigError("load.fixity", "clamped", "pinned with load.mode: free (a clamp needs an anchor or an ROV to hold it)");
  }
  if (p.winch.enabled) {
    if (!p.attachments.empty()) {
      // The winch's link changes length and the links move along their slots as it pays out: an
      // attachment would have to ride through the winch (not modelled).
      throw ConfigError("attachments", std::to_string(p.attachments.size()) + " given", "none with a winch (not modelled yet)");
    }
    // The winch's link moves with the paid-out cable and has a length of its own: the recursion's
    // formulation, and springs of the bending model (docs/MODEL.md section 8).
    if (p.simulation.formulation != Formulation::kRecursive) {
      throw ConfigError("simulation.formulation", "paper", "recursive with a winch");
    }
    if (p.simulation.integrator == Integrator::kSemiImplicit) {
      throw ConfigError("simulation.integrator", integratorName(p.simulation.integrator), "rk4 or implicit with a winch");
    }
    if (k.model == StiffnessModel::kPaper && (k.elevation > 0.0 || p.damping.elevation > 0.0)) {
      throw ConfigError("cable.stiffness.model", "paper", "bending when a winch pays out a cable with springs or dampers");
    }
  }
  if (p.load.fixity == TipFixity::kClamped && k.model != StiffnessModel::kBending) {
    throw ConfigError("load.fixity", "clamped", "pinned with cable.stiffness.model: paper; use model: bending");
  }
  // The paper's springs act on absolute angles measured from the vertical: a clamp direction or a pin
  // has no meaning for them.
  const bool default_base = p.base.fixity == BaseFixity::kClamped && (p.base.direction + Eigen::Vector3d::UnitZ()).norm() < 1e-12;
  if (k.model == StiffnessModel::kPaper && !default_base) {
    throw ConfigError(p.base.fixity == BaseFixity::kPinned ? "base.fixity" : "base.direction",
                      p.base.fixity == BaseFixity::kPinned ? "pinned" : "not straight down",
                      "the default (clamped, [0, 0, -1]) with cable.stiffness.model: paper; use model: bending");
  }
}

void checkSimulatorRules(const CableParams& p) {
  // The paper's azimuth and torsion springs and dampers act on angles that are not defined when a link
  // hangs straight down; their torque grows like 1/sin(te) there (docs/MODEL.md section 5).
  if (p.stiffness.model == StiffnessModel::kPaper) {
    const std::pair<const char*, double> values[] = {
        {"cable.stiffness.azimuth", p.stiffness.azimuth},
        {"cable.stiffness.torsion", p.stiffness.torsion},
        {"cable.stiffness.torsional_rigidity", p.stiffness.torsional_rigidity},
        {"cable.stiffness.bending_rigidity", p.stiffness.bending_rigidity},
        {"cable.damping.azimuth", p.damping.azimuth},
        {"cable.damping.torsion", p.damping.torsion}};
    for (const auto& [key, value] : values) {
      if (value != 0.0) {
        throw ConfigError(key, formatNumber(value),
                          "0 with cable.stiffness.model: paper in the simulator (the paper's azimuth and torsion "
                          "springs and dampers are singular at the vertical); use model: bending");
      }
    }
    // The paper's elevation damper acts along the azimuth's direction, which swings fast as a link
    // passes near the vertical: the semi-implicit step, which holds directions over a long step,
    // mis-tracks it (measured: a 10 ms step stalls the current preset away from its steady state). RK4
    // tracks it.
    if (p.simulation.integrator == Integrator::kSemiImplicit && p.damping.elevation != 0.0) {
      throw ConfigError("cable.damping.elevation", formatNumber(p.damping.elevation),
                        "0 with simulation.integrator: semi_implicit unless cable.stiffness.model is bending (or use "
                        "integrator: rk4)");
    }
    // The implicit integrator folds the bending model's joint springs into its recursion; the paper's
    // elevation spring and damper act on an absolute angle and are not among its Jacobians.
    if (p.simulation.integrator == Integrator::kImplicit && (p.stiffness.elevation != 0.0 || p.damping.elevation != 0.0)) {
      const bool spring = p.stiffness.elevation != 0.0;
      throw ConfigError(spring ? "cable.stiffness.elevation" : "cable.damping.elevation",
                        formatNumber(spring ? p.stiffness.elevation : p.damping.elevation),
                        "0 with simulation.integrator: implicit unless cable.stiffness.model is bending (or use "
                        "integrator: rk4)");
    }
  }
}

bool positionAllowed(const Eigen::Vector3d& position) {
  return position.allFinite() && position.cwiseAbs().maxCoeff() <= kMaxInputPosition;
}

bool velocityAllowed(const Eigen::Vector3d& velocity) {
  // A tracker's velocity is a distance within kMaxInputSpeed * interval divided by that interval: the
  // quotient may exceed the limit by a rounding error.
  return velocity.allFinite() && velocity.norm() <= kMaxInputSpeed * (1.0 + 1e-12);
}

bool currentAllowed(const Eigen::Vector3d& current) {
  return current.allFinite() && current.cwiseAbs().maxCoeff() <= kMaxCurrentSpeed;
}

bool winchSpeedAllowed(double speed, double max_speed) { return std::isfinite(speed) && std::abs(speed) <= max_speed; }

void checkPosition(const char* key, const Eigen::Vector3d& position) {
  if (!positionAllowed(position)) {
    refuse(key, formatVector(position), "finite components within +-" + number(kMaxInputPosition) + " m");
  }
}

void checkVelocity(const char* key, const Eigen::Vector3d& velocity) {
  if (!velocityAllowed(velocity)) {
    refuse(key, formatVector(velocity), "a finite velocity of at most " + number(kMaxInputSpeed) + " m/s");
  }
}

bool thrustAllowed(const Eigen::Vector3d& thrust) {
  return thrust.allFinite() && thrust.cwiseAbs().maxCoeff() <= kMaxThrust;
}

void checkThrust(const char* key, const Eigen::Vector3d& thrust) {
  if (!thrustAllowed(thrust)) refuse(key, formatVector(thrust), "finite components within +-" + number(kMaxThrust));
}

void checkAttitude(const char* key, const Eigen::Quaterniond& attitude) {
  if (!attitude.coeffs().allFinite() || std::abs(attitude.norm() - 1.0) > 1e-6) {
    refuse(key, formatVector(attitude.coeffs()), "a finite unit quaternion (x, y, z, w)");
  }
}

void checkCurrent(const Eigen::Vector3d& current) {
  for (int i = 0; i < 3; ++i) {
    if (!ranges::kCurrent.allows(current(i))) {
      throw ConfigError("fluid.current[" + std::to_string(i) + "]", number(current(i)), ranges::kCurrent.text());
    }
  }
}

void checkWinchSpeed(double speed, const WinchParams& winch) {
  if (!winchSpeedAllowed(speed, winch.max_speed)) {
    refuse("winch speed", number(speed),
           "a finite speed within +-" + number(winch.max_speed) + " m/s (winch.max_speed)");
  }
}

void checkWinchLength(double length, const WinchParams& winch) {
  if (!std::isfinite(length) || length < winch.min_length || length > winch.max_length) {
    refuse("winch length", number(length),
           "a finite length in [" + number(winch.min_length) + ", " + number(winch.max_length) +
               "] m (winch.min_length, winch.max_length)");
  }
}

}  // namespace cable_dynamics
