#include "cable_dynamics/simulation/time_schemes/rk4.h"

#include "cable_dynamics/dynamics/hot_path.h"

namespace cable_dynamics {

// The stages' vector arithmetic as plain loops in the hot path's clones (hot_path.h): as Eigen
// expressions in the baseline build they ran two doubles an instruction, a twentieth of a ten-link step.
// Not in an anonymous namespace: the loader's dispatch (an ifunc) needs a symbol it can see.
namespace rk4_detail {

/// out = x + a k over m entries.
CABLE_HOT_PATH void stage(double* out, const double* x, double a, const double* k, int m) {
  for (int i = 0; i < m; ++i) out[i] = x[i] + a * k[i];
}

/// x += h/6 (k1 + 2 k2 + 2 k3 + k4) over m entries.
CABLE_HOT_PATH void combine(double* x, double h, const double* k1, const double* k2, const double* k3, const double* k4,
                            int m) {
  const double sixth = h / 6.0;
  for (int i = 0; i < m; ++i) x[i] += sixth * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

}  // namespace rk4_detail

Rk4Scheme::Rk4Scheme(int state_size) {
  for (Eigen::VectorXd* v : {&k1_, &k2_, &k3_, &k4_, &stage_}) v->setZero(state_size);
}

bool Rk4Scheme::advance(ChainDynamics& f, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) {
  const bool start_known = start_known_;
  start_known_ = false;
  // Only the moving tail of x: a winch's drum slots (the head) neither move nor are read.
  const int m = StateLayout::moving(x.size(), f.deployed().firstLink());
  const Eigen::Index head = x.size() - m;  // the tail of every vector starts here
  const auto tail = [head](Eigen::VectorXd& v) { return v.data() + head; };
  double* const xt = tail(x);
  if (!start_known && !f.derivative(x, ends.at(t), k1_)) return false;
  rk4_detail::stage(tail(stage_), xt, 0.5 * h, tail(k1_), m);
  if (!f.derivative(stage_, ends.at(t + 0.5 * h), k2_)) return false;
  rk4_detail::stage(tail(stage_), xt, 0.5 * h, tail(k2_), m);
  if (!f.derivative(stage_, ends.at(t + 0.5 * h), k3_)) return false;
  rk4_detail::stage(tail(stage_), xt, h, tail(k3_), m);
  if (!f.derivative(stage_, ends.at(t + h), k4_)) return false;
  rk4_detail::combine(xt, h, tail(k1_), tail(k2_), tail(k3_), tail(k4_), m);
  return true;
}

bool Rk4Scheme::evaluateEnd(ChainDynamics& f, const EndInputs& ends, const Eigen::VectorXd& x) {
  start_known_ = f.derivative(x, ends, k1_);
  return start_known_;
}

}  // namespace cable_dynamics
