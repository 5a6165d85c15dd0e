#include "cable_dynamics/simulation/time_schemes/rk4.h"

namespace cable_dynamics {

Rk4Scheme::Rk4Scheme(int state_size) {
  for (Eigen::VectorXd* v : {&k1_, &k2_, &k3_, &k4_, &stage_}) v->setZero(state_size);
}

bool Rk4Scheme::advance(ChainDynamics& f, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) {
  const bool start_known = start_known_;
  start_known_ = false;
  // Only the moving tail of x: a winch's drum slots (the head) neither move nor are read.
  const int m = StateLayout::moving(x.size(), f.deployed().firstLink());
  if (!start_known && !f.derivative(x, ends.at(t), k1_)) return false;
  stage_.tail(m) = x.tail(m) + 0.5 * h * k1_.tail(m);
  if (!f.derivative(stage_, ends.at(t + 0.5 * h), k2_)) return false;
  stage_.tail(m) = x.tail(m) + 0.5 * h * k2_.tail(m);
  if (!f.derivative(stage_, ends.at(t + 0.5 * h), k3_)) return false;
  stage_.tail(m) = x.tail(m) + h * k3_.tail(m);
  if (!f.derivative(stage_, ends.at(t + h), k4_)) return false;
  x.tail(m) += (h / 6.0) * (k1_.tail(m) + 2.0 * k2_.tail(m) + 2.0 * k3_.tail(m) + k4_.tail(m));
  return true;
}

bool Rk4Scheme::evaluateEnd(ChainDynamics& f, const EndInputs& ends, const Eigen::VectorXd& x) {
  start_known_ = f.derivative(x, ends, k1_);
  return start_known_;
}

}  // namespace cable_dynamics
