#pragma once
/// \file
/// \brief Classical fourth-order Runge-Kutta, with the first stage taken from the previous step's end.

#include "cable_dynamics/simulation/time_schemes/time_scheme.h"

namespace cable_dynamics {

/// x_{n+1} = x_n + h/6 (k1 + 2 k2 + 2 k3 + k4). Fourth order; stable for |h lambda| below about 2.8 on
/// the imaginary axis (oscillations) and 2.78 on the real axis (damping). The first stage k1 is the x'
/// that evaluateEnd() computed at the end of the step before (four evaluations a step become three
/// plus the end's, which the energy check needs anyway), unless forget() was called in between.
class Rk4Scheme : public TimeScheme {
 public:
  explicit Rk4Scheme(int state_size);

  bool advance(ChainDynamics& dynamics, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) override;
  bool balancesEnergy() const override { return true; }
  bool evaluateEnd(ChainDynamics& dynamics, const EndInputs& ends, const Eigen::VectorXd& x) override;
  void forget() override { start_known_ = false; }

  std::unique_ptr<TimeScheme> clone() const override { return std::make_unique<Rk4Scheme>(*this); }

 private:
  bool start_known_ = false;  ///< k1_ holds x' at the state the next advance() starts from
  Eigen::VectorXd k1_, k2_, k3_, k4_, stage_;  ///< (state size)
};

}  // namespace cable_dynamics
