#include "catenary_start.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "static_start.h"

namespace cable_dynamics {
namespace statics {

Eigen::Vector2d ElasticCatenary::top(double h, double v) const {
  const double c = compliance_, w = w_, length = length_;
  if (grounded_ && v < w * length) {
    // Suspended from the touchdown, where the vertical tension is zero, over L_s = V / w; the grounded rest
    // lies straight, stretched by H.
    const double suspended = std::max(v, 0.0) / w, bed = length - suspended;
    return {bed + h * length * c + h / w * std::asinh(v / h),
            0.5 * w * suspended * suspended * c + h / w * (std::hypot(1.0, v / h) - 1.0)};
  }
  const double va = v - w * length;  // at the anchor
  return {h * length * c + h / w * (std::asinh(v / h) - std::asinh(va / h)),
          c * (va * length + 0.5 * w * length * length) + h / w * (std::hypot(1.0, v / h) - std::hypot(1.0, va / h))};
}

bool ElasticCatenary::solve(double length, double weight, double axial_stiffness, double span, double rise, bool grounded) {
  length_ = length;
  w_ = weight;
  compliance_ = std::isfinite(axial_stiffness) && axial_stiffness > 0.0 ? 1.0 / axial_stiffness : 0.0;
  grounded_ = grounded;
  if (!(length > 0.0 && weight > 0.0 && span > 1e-6 * length)) return false;
  // The usual first guess (Peyrot and Goulois 1979): a parabola's sag parameter lambda from how much
  // longer the line is than its chord; 0.2 for a taut one.
  const double slack = (length * length - rise * rise) / (span * span) - 1.0;
  const double lambda = slack > 0.0 ? std::max(std::sqrt(3.0 * slack), 0.2) : 0.2;
  Eigen::Vector2d z(weight * span / (2.0 * lambda), 0.5 * weight * (rise / std::tanh(lambda) + length));
  const Eigen::Vector2d goal(span, rise);
  const double scale = span + std::abs(rise) + length;
  Eigen::Vector2d r = top(z(0), z(1)) - goal;
  for (int it = 0; it < 100 && r.norm() > 1e-12 * scale; ++it) {
    Eigen::Matrix2d jacobian;
    const double dh = 1e-7 * z(0), dv = 1e-7 * std::max(std::abs(z(1)), weight * length);
    jacobian.col(0) = (top(z(0) + dh, z(1)) - top(z(0) - dh, z(1))) / (2.0 * dh);
    jacobian.col(1) = (top(z(0), z(1) + dv) - top(z(0), z(1) - dv)) / (2.0 * dv);
    Eigen::Vector2d step = jacobian.partialPivLu().solve(-r);
    if (!step.allFinite()) return false;
    // Backtracking: H stays positive and the residual falls.
    double factor = 1.0;
    Eigen::Vector2d next = z + step, next_r;
    for (int half = 0; half < 40; ++half, factor *= 0.5) {
      next = z + factor * step;
      if (next(0) > 0.0 && (next_r = top(next(0), next(1)) - goal).allFinite() && next_r.norm() < r.norm()) break;
    }
    if (!(next(0) > 0.0) || !next_r.allFinite()) return false;
    z = next;
    r = next_r;
  }
  if (!(r.norm() <= 1e-9 * scale)) return false;
  h_ = z(0);
  top_vertical_ = z(1);
  grounded_length_ = grounded_ && top_vertical_ < w_ * length_ ? length_ - std::max(top_vertical_, 0.0) / w_ : 0.0;
  return true;
}

CatenaryPoint ElasticCatenary::at(double sigma) const {
  const double h = h_, c = compliance_, w = w_;
  CatenaryPoint p;
  if (grounded_length_ > 0.0) {
    const double bed = grounded_length_;
    if (sigma <= bed) return {sigma * (1.0 + h * c), 0.0, h};
    const double up = sigma - bed, v = w * up;
    p.along = bed + h * sigma * c + h / w * std::asinh(v / h);
    p.height = 0.5 * w * up * up * c + h / w * (std::hypot(1.0, v / h) - 1.0);
    p.tension = std::hypot(h, v);
    return p;
  }
  const double va = top_vertical_ - w * length_, v = va + w * sigma;
  p.along = h * sigma * c + h / w * (std::asinh(v / h) - std::asinh(va / h));
  p.height = c * (va * sigma + 0.5 * w * sigma * sigma) + h / w * (std::hypot(1.0, v / h) - std::hypot(1.0, va / h));
  p.tension = std::hypot(h, v);
  return p;
}

bool catenaryStart(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                   const StaticProblem& problem, StaticState& s, Eigen::VectorXd& stretch, Eigen::Vector3d& target) {
  const LinkProperties& p = deployed.properties();
  const int n = model.links(), first = problem.first_link;
  if (!problem.tip_coupled || !(model.holdStiffness() > 0.0) || !p.attachments.empty()) return false;
  if (!current.uniform() || !current.uniformValue().isZero()) return false;
  // One weight per length and one EA over the deployed links (a locked last stretch, EA 0, aside).
  double length = 0.0, weight = std::numeric_limits<double>::quiet_NaN(), axial = 0.0;
  for (int k = first; k < n; ++k) {
    const double l = p.length(k);
    if (!(l > 0.0)) return false;
    const double w = p.gravity * p.submerged_mass(k) / l;
    if (std::isnan(weight)) weight = w;
    if (std::abs(w - weight) > 1e-9 * std::abs(weight)) return false;
    const double ea = deployed.get(&LinkConstants::axial_stiffness, k) * l;
    if (ea > 0.0) {
      if (axial > 0.0 && std::abs(ea - axial) > 1e-9 * axial) return false;
      axial = ea;
    }
    length += l;
  }
  if (!(weight > 0.0)) return false;
  const Eigen::Vector3d& anchor = problem.target_position;
  const Eigen::Vector3d chord = anchor - problem.base_position;  // paper frame, z down
  const double span = chord.head<2>().norm(), rise = chord.z();
  // The bed: the anchor sits on it (within the allowed penetration), the grounded part lies on it. A line
  // clear of any bed starts well from the limp sweep already (the jumper, 9 iterations), and its answer
  // would only move within Newton's tolerance.
  const SeabedContactConstants& bed = model.seabedContact();
  if (!bed.enabled() || !bed.bed.flat() || std::abs(anchor.z() - bed.bed.shallowest()) > bed.allowed_penetration) {
    return false;
  }
  if (StaticEquations(model, deployed, current, problem).hasBendSprings()) return false;  // its bend or tip clamp
  ElasticCatenary catenary;
  if (!catenary.solve(length, weight, axial > 0.0 ? axial : std::numeric_limits<double>::infinity(), span, rise, true)) {
    return false;
  }
  StaticProblem shifted = problem;
  const Eigen::Vector3d toward_anchor = Eigen::Vector3d(chord.x(), chord.y(), 0.0) / span;
  const auto point = [&](const CatenaryPoint& c) {  // in the paper frame [m]
    return Eigen::Vector3d(anchor - c.along * toward_anchor - c.height * Eigen::Vector3d::UnitZ());
  };
  StaticState start;
  start.resize(n - first);
  Eigen::VectorXd stretches = Eigen::VectorXd::Zero(n);
  // Each link from its base end's point to its far end's, sigma from the anchor; the far end's is the next
  // link's base end.
  double sigma = length;
  Eigen::Vector3d base_end = point(catenary.at(sigma));
  for (int k = first; k < n; ++k) {
    sigma = std::max(sigma - p.length(k), 0.0);
    const CatenaryPoint far = catenary.at(sigma);
    const Eigen::Vector3d far_end = point(far);
    start.axis.col(k - first) = (far_end - base_end).normalized();
    const double spring = deployed.get(&LinkConstants::axial_stiffness, k);
    if (spring > 0.0) stretches(k) = far.tension / spring;
    base_end = far_end;
  }
  // The line's pull on the anchor, along its end towards the base: the hold's spring k (target - tip) must
  // give its opposite with the tip on the anchor.
  const Eigen::Vector3d pull =
      -(catenary.horizontalTension() * toward_anchor + catenary.anchorVertical() * Eigen::Vector3d::UnitZ());
  shifted.target_position = anchor - pull / staticHoldStiffness(model);
  if (model.axial()) shifted.stretch = stretches;
  const StaticEquations eq(model, deployed, current, shifted);
  forcesForAxes(eq, start);
  if (!start.axis.allFinite() || !start.force.allFinite() || !shifted.target_position.allFinite()) return false;
  s = start;
  stretch = stretches;
  target = shifted.target_position;
  return true;
}

}  // namespace statics
}  // namespace cable_dynamics
