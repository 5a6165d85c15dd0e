#pragma once
/// \file
/// \brief cable_dynamics itself as one system of the benchmark: CableSimulator::step(), and
///        ChainDynamics::derivative() (the hot function) timed on its own.

#include <string>
#include <vector>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "chain_spec.h"

namespace bench {

/// The formulations to time: {""} (the one there is), or {"paper", "recursive"} when the config
/// accepts simulation.formulation=recursive.
std::vector<std::string> projectFormulations();

class ProjectSystem : public System {
 public:
  /// `formulation` empty: no simulation.formulation key at all (the project's default).
  ProjectSystem(int links, const std::string& formulation);

  const cable_dynamics::CableParams& params() const { return params_; }
  /// Link axes of the initial state (paper frame, z down).
  std::vector<Eigen::Vector3d> initialAxes() const;

  void reset() override;
  void step() override;
  double energy() override;
  Eigen::Vector3d tip() override;
  bool healthy() const override { return failed_since_reset_ == 0; }
  std::string note() const override;

  /// One ChainDynamics::derivative() call at the initial state (what each RK4 stage calls).
  void derivative();
  /// x' at the initial state; false when derivative() fails there.
  bool derivativeAtStart(Eigen::VectorXd& xdot);

 private:
  cable_dynamics::CableParams params_;
  cable_dynamics::CableSimulator sim_;
  Eigen::VectorXd x0_, xdot_;
  long retried_steps_ = 0, failed_steps_ = 0, failed_since_reset_ = 0;
};

}  // namespace bench
