#include "static_newton.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "static_start.h"

namespace cable_dynamics {
namespace statics {
namespace {

/// A basis (e1, e2) of the plane normal to the unit vector u, e1 x e2 = u (Duff et al. 2017). It jumps
/// where u.z changes sign, so it is only ever used fixed, from one iterate.
void normalBasis(const Eigen::Vector3d& u, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const double sign = std::copysign(1.0, u.z());
  const double a = -1.0 / (sign + u.z()), b = u.x() * u.y() * a;
  e1 = Eigen::Vector3d(1.0 + sign * u.x() * u.x() * a, sign * b, -sign * u.x());
  e2 = Eigen::Vector3d(b, sign + u.y() * u.y() * a, -u.y());
}

/// u turned by the tangent vector t (normal to u) along the great circle: the exponential map.
Eigen::Vector3d turned(const Eigen::Vector3d& u, const Eigen::Vector3d& t) {
  const double angle = t.norm();
  const double sinc = angle > 1e-8 ? std::sin(angle) / angle : 1.0 - angle * angle / 6.0;
  return (std::cos(angle) * u + sinc * t).normalized();
}

}  // namespace

StaticNewton::StaticNewton(const StaticEquations& eq) : eq_(eq), m_(eq.links()), e1_(3, m_), e2_(3, m_) {
  trial_.resize(m_);
  system_.resize(m_);
  step_.resize(kUnknowns, m_);
}

Vector8 StaticNewton::scaled(const StaticState& s, int i) {
  eq_.residual(s, i, r_);
  const double l = eq_.length(i), moment_scale = 1.0 / (force_scale_ * l);
  Vector8 v;
  v.head<3>() = r_.force / force_scale_;
  v(3) = r_.moment.dot(e1_.col(i)) * moment_scale;
  v(4) = r_.moment.dot(e2_.col(i)) * moment_scale;
  v.tail<3>() = r_.closure / l;
  return v;
}

double StaticNewton::merit(const StaticState& s) {
  double sum = 0.0;
  for (int i = 0; i < m_; ++i) {
    eq_.residual(s, i, r_);
    const double l = eq_.length(i);
    // The moment is normal to u_i, so its norm is that of its two components on any normal basis.
    sum += r_.force.squaredNorm() / (force_scale_ * force_scale_) +
           r_.moment.squaredNorm() / (force_scale_ * force_scale_ * l * l) + r_.closure.squaredNorm() / (l * l);
  }
  return sum;
}

double StaticNewton::relativeResidual(const StaticState& s) {
  force_scale_ = eq_.forceScale(s);
  double worst = 0.0;
  for (int i = 0; i < m_; ++i) {
    eq_.residual(s, i, r_);
    const double l = eq_.length(i);
    worst = std::max({worst, r_.force.norm() / force_scale_, r_.moment.norm() / (force_scale_ * l),
                      r_.closure.norm() / l});
  }
  return worst;
}

void StaticNewton::referenceBases(const StaticState& s) {
  for (int i = 0; i < m_; ++i) {
    Eigen::Vector3d a, b;
    normalBasis(s.axis.col(i), a, b);
    e1_.col(i) = a;
    e2_.col(i) = b;
  }
}

void StaticNewton::jacobian(StaticState& s) {
  // Column by column, central differences: unknown v of link j enters the residuals of links j-1, j
  // and j+1 only, so each perturbation evaluates three links (O(n) in all).
  for (int j = 0; j < m_; ++j) {
    const Eigen::Vector3d force = s.force.col(j), axis = s.axis.col(j), base = s.base.col(j);
    const double l = eq_.length(j);
    for (int v = 0; v < kUnknowns; ++v) {
      // Steps: 1e-6 of the unknown's scale (F [N], 1 rad, l_j [m]); round-off ~1e-10, truncation ~1e-12.
      const double h = v < 3 ? 1e-6 * force_scale_ : (v < 5 ? 1e-6 : 1e-6 * l);
      Vector8 plus[3], minus[3];
      for (int side = 0; side < 2; ++side) {
        const double d = side == 0 ? h : -h;
        if (v < 3) {
          s.force(v, j) = force(v) + d;
        } else if (v < 5) {
          s.axis.col(j) = turned(axis, d * (v == 3 ? e1_.col(j) : e2_.col(j)));
        } else {
          s.base(v - 5, j) = base(v - 5) + d;
        }
        Vector8* out = side == 0 ? plus : minus;
        for (int row = std::max(j - 1, 0); row <= std::min(j + 1, m_ - 1); ++row) out[row - j + 1] = scaled(s, row);
        s.force.col(j) = force;
        s.axis.col(j) = axis;
        s.base.col(j) = base;
      }
      const double inverse = 1.0 / (2.0 * h);
      if (j > 0) system_.upper(j - 1).col(v) = (plus[0] - minus[0]) * inverse;
      system_.diagonal(j).col(v) = (plus[1] - minus[1]) * inverse;
      if (j + 1 < m_) system_.lower(j + 1).col(v) = (plus[2] - minus[2]) * inverse;
    }
  }
}

void StaticNewton::applyStep(const StaticState& from, double alpha, StaticState& to) const {
  for (int i = 0; i < m_; ++i) {
    const auto z = step_.col(i);
    to.force.col(i) = from.force.col(i) + alpha * z.head<3>();
    to.axis.col(i) = turned(from.axis.col(i), alpha * (z(3) * e1_.col(i) + z(4) * e2_.col(i)));
    to.base.col(i) = from.base.col(i) + alpha * z.tail<3>();
  }
}

bool StaticNewton::solve(StaticState& s, double tolerance, int max_iterations, int& iterations, double& residual,
                         std::string& why, int min_iterations) {
  iterations = 0;
  for (;;) {
    residual = relativeResidual(s);  // also sets F for this iteration
    if (!std::isfinite(residual)) {
      why = "the residual is not finite";
      return false;
    }
    if (residual < tolerance && iterations >= min_iterations) {
      // The dynamics place the links from the axes alone, so a closure error of e [m] reaches the tip
      // as a coupling force k_c e: judge the state with the base ends from the axes and the forces
      // from the tip (force balance and closure then exact, the moments what the dynamics see). Newton
      // goes on from there when that is not converged yet.
      trial_ = s;
      forcesForAxes(eq_, trial_);
      residual = relativeResidual(trial_);
      std::swap(s, trial_);
      if (residual < tolerance) return true;
    }
    if (iterations >= max_iterations) {
      std::ostringstream text;
      text << "no convergence in " << max_iterations << " Newton iterations: relative residual " << residual;
      why = text.str();
      return false;
    }
    ++iterations;
    referenceBases(s);
    jacobian(s);
    for (int i = 0; i < m_; ++i) step_.col(i) = -scaled(s, i);
    if (!system_.solve(step_)) {
      std::ostringstream text;
      text << "singular Jacobian (a slack link?) at relative residual " << residual;
      why = text.str();
      return false;
    }
    // Backtracking on the sum of squares (Armijo, the Newton direction's slope is -2 merit); no link
    // turns by more than 0.5 rad in one step, so a far start cannot flip links over.
    double largest_turn = 0.0;
    for (int i = 0; i < m_; ++i) largest_turn = std::max(largest_turn, step_.col(i).segment<2>(3).norm());
    double alpha = std::min(1.0, 0.5 / std::max(largest_turn, 1e-300));
    const double start = merit(s);
    bool accepted = false;
    for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
      applyStep(s, alpha, trial_);
      const double trial = merit(trial_);
      if (std::isfinite(trial) && trial <= (1.0 - 1e-4 * alpha) * start) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      std::ostringstream text;
      text << "the line search found no decrease at relative residual " << residual;
      why = text.str();
      return false;
    }
    std::swap(s, trial_);
  }
}

}  // namespace statics
}  // namespace cable_dynamics
