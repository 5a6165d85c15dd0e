#include "static_start.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/LU>

namespace cable_dynamics {
namespace statics {
namespace {

void basesFromAxes(const StaticEquations& eq, StaticState& s) {
  Eigen::Vector3d p = eq.problem().base_position;
  for (int i = 0; i < eq.links(); ++i) {
    s.base.col(i) = p;
    p += eq.length(i) * s.axis.col(i);
  }
}

}  // namespace

void forcesForAxes(const StaticEquations& eq, StaticState& s) {
  basesFromAxes(eq, s);
  Eigen::Vector3d next = eq.outboardForce(s, eq.links() - 1), f, n;
  for (int i = eq.links() - 1; i >= 0; --i) {
    eq.linkLoads(i, s.axis.col(i), s.base.col(i), f, n);
    s.force.col(i) = next - f;
    next = s.force.col(i);
  }
}

void straightStart(const StaticEquations& eq, const Eigen::Vector3d& direction, StaticState& s) {
  for (int i = 0; i < eq.links(); ++i) s.axis.col(i) = direction;
  forcesForAxes(eq, s);
}

void sweepLimp(const StaticEquations& eq, const Eigen::Vector3d& pull, StaticState& s) {
  const int m = eq.links();
  // Uniform current: the loads do not depend on depth, one pass is exact. A profile: the depths of
  // the previous pass, until the tip stops moving (a fixed point: the drag's depth gradient is weak
  // against the tension that carries it).
  const int passes = eq.uniformCurrent() ? 1 : 100;
  Eigen::Vector3d last_tip = eq.tip(s);
  for (int pass = 0; pass < passes; ++pass) {
    Eigen::Vector3d next = -(eq.loadForceFree(eq.tip(s)) + pull), f, n;
    for (int i = m - 1; i >= 0; --i) {
      const Eigen::Vector3d p = s.base.col(i);
      const double l = eq.length(i);
      Eigen::Vector3d u = s.axis.col(i);
      for (int iteration = 0; iteration < 30; ++iteration) {
        eq.linkLoads(i, u, p, f, n);
        const Eigen::Vector3d v = n - l * next;  // the moment about the base end is u x v
        const double norm = v.norm();
        if (!(norm > 1e-300)) break;  // nothing pulls this link: keep the guess
        const Eigen::Vector3d updated = v / norm;
        const bool settled = (updated - u).norm() < 1e-15;
        u = updated;
        if (settled) break;
      }
      eq.linkLoads(i, u, p, f, n);
      s.axis.col(i) = u;
      s.force.col(i) = next - f;
      next = s.force.col(i);
    }
    basesFromAxes(eq, s);
    const Eigen::Vector3d tip = eq.tip(s);
    if ((tip - last_tip).norm() < 1e-15 * eq.deployedLength()) break;
    last_tip = tip;
  }
}

bool shootCoupled(const StaticEquations& eq, StaticState& s, std::string& why) {
  const Eigen::Vector3d base = eq.problem().base_position, target = eq.problem().target_position;
  const double length = eq.deployedLength(), stiffness = eq.couplingStiffness();
  // First guess of the pull, from a parabola over the chord: sag h with L - D = 8 h^2 / (3 D), the
  // chord-wise tension H = w D^2 / (8 h), and the tip carrying half the external load.
  const Eigen::Vector3d chord = target - base;
  const double distance = chord.norm();
  const Eigen::Vector3d direction = distance > 1e-9 * length ? Eigen::Vector3d(chord / distance) : Eigen::Vector3d::UnitZ();
  straightStart(eq, direction, s);
  Eigen::Vector3d load = eq.loadForceFree(eq.tip(s)), f, n;
  for (int i = 0; i < eq.links(); ++i) {
    eq.linkLoads(i, s.axis.col(i), s.base.col(i), f, n);
    load += f;
  }
  const double sag = std::sqrt(3.0 * distance * std::max(length - distance, 1e-6 * length) / 8.0);
  const double chordwise = load.norm() * distance * distance / (8.0 * std::max(sag, 1e-9 * length) * length);
  Eigen::Vector3d pull = -0.5 * load + chordwise * direction;

  const auto residual = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    sweepLimp(eq, p, s);
    return eq.tip(s) - target + p / stiffness;
  };
  Eigen::Vector3d r = residual(pull);
  const double scale = std::max(load.norm(), 1e-9);  // [N]
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (r.norm() < 1e-13 * length) return true;
    Eigen::Matrix3d jacobian;
    const double h = 1e-6 * std::max(pull.norm(), scale);
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d plus = pull, minus = pull;
      plus(c) += h;
      minus(c) -= h;
      jacobian.col(c) = (residual(plus) - residual(minus)) / (2.0 * h);
    }
    const Eigen::Vector3d step = -jacobian.partialPivLu().solve(r);
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 40 && step.allFinite(); ++halving, alpha *= 0.5) {
      const Eigen::Vector3d trial = residual(pull + alpha * step);
      if (trial.allFinite() && trial.norm() < (1.0 - 1e-4 * alpha) * r.norm()) {
        pull += alpha * step;
        r = trial;
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
  }
  r = residual(pull);  // leave s at the best pull
  if (r.norm() < 1e-9 * length) return true;
  std::ostringstream text;
  text << "the limp start did not meet the target: tip " << r.norm() << " m off";
  why = text.str();
  return false;
}

}  // namespace statics
}  // namespace cable_dynamics
