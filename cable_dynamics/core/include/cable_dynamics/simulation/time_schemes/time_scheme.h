#pragma once
/// \file
/// \brief The time schemes that step x' = f(t, x), as a family apart from the model they step (as
///        MuJoCo's integrators and MoorDyn's time schemes are): one interface, one file each, chosen by
///        the Integrator enum.

#include <limits>
#include <memory>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/end_conditions.h"
#include "cable_dynamics/simulation/step_check.h"

namespace cable_dynamics {

/// One fixed-step scheme. Holds its own workspace (sized at construction: no allocation in a step).
class TimeScheme {
 public:
  virtual ~TimeScheme() = default;

  /// Advances the state x (StateLayout) from time t [s] by h [s], with the ends' inputs `ends` gives at
  /// each stage. Returns false when an evaluation fails (a non-finite state or acceleration, a mass
  /// matrix that is not positive definite, a singular linear system); x is then unspecified.
  virtual bool advance(ChainDynamics& dynamics, const EndConditions& ends, double t, double h,
                       Eigen::VectorXd& x) = 0;

  /// true when the scheme's energy balance holds to its order, so that a step that creates energy has
  /// gone unstable (RK4); false for the semi-implicit scheme, whose power terms are first order.
  virtual bool balancesEnergy() const = 0;
  /// For a scheme that does not (balancesEnergy() false): the rise of the energy balance in one step,
  /// relative to its scale (step_check.h), beyond which the step is retried in pieces; infinity where the
  /// balance is only followed. The semi-implicit step books its powers at the step's start (first order):
  /// a start from rest in a flow reads as a rise of all the kinetic energy it gains, at any step.
  virtual double riseTolerance(const StepLimits& /*limits*/) const { return std::numeric_limits<double>::infinity(); }

  /// Evaluates x' at the end state x of a step (inputs `ends`), leaving its kinematics in the dynamics'
  /// data for the energy check. RK4 keeps that x' as the next step's first stage (the "first same as
  /// last" reuse) until forget(). Returns false when x' is not finite.
  virtual bool evaluateEnd(ChainDynamics& dynamics, const EndInputs& ends, const Eigen::VectorXd& x);

  /// An input changed or a step was discarded: nothing evaluated earlier may be reused.
  virtual void forget() {}
  /// An input that enters the rates but not their Jacobian changed (an ROV body's thrust): the rates
  /// evaluated earlier may not be reused (RK4's first stage), a Jacobian may.
  virtual void forgetRates() { forget(); }

  /// A copy, workspace and all (a trial simulator: CableSimulator's copy).
  virtual std::unique_ptr<TimeScheme> clone() const = 0;
};

/// Owns one scheme and copies it by clone(), so that a CableSimulator is copied as a whole.
class SchemeHolder {
 public:
  explicit SchemeHolder(std::unique_ptr<TimeScheme> scheme) : scheme_(std::move(scheme)) {}
  SchemeHolder(const SchemeHolder& other) : scheme_(other.scheme_ ? other.scheme_->clone() : nullptr) {}
  SchemeHolder(SchemeHolder&&) = default;
  SchemeHolder& operator=(const SchemeHolder& other) {
    if (this != &other) scheme_ = other.scheme_ ? other.scheme_->clone() : nullptr;
    return *this;
  }
  SchemeHolder& operator=(SchemeHolder&&) = default;
  TimeScheme* operator->() const { return scheme_.get(); }
  TimeScheme& operator*() const { return *scheme_; }

 private:
  std::unique_ptr<TimeScheme> scheme_;
};

/// The scheme `integrator` for chains of `links` links (rho_infinity: the implicit scheme's, SimulationParams),
/// with an ROV body on the tip when `body` (load.mode body: the state's last StateLayout::kBody entries).
/// With the links' stretch in the state when `axial` (RK4 only so far: the config gate refuses the others).
std::unique_ptr<TimeScheme> makeTimeScheme(Integrator integrator, int links, double rho_infinity = 1.0, bool body = false,
                                           bool axial = false);

}  // namespace cable_dynamics
