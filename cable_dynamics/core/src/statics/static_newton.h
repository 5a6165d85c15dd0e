#pragma once
// Newton's method on the block tridiagonal equilibrium equations (static_solver.h). Internal to the statics.

#include <string>

#include <Eigen/Core>

#include "cable_dynamics/statics/block_tridiagonal.h"
#include "static_equations.h"

namespace cable_dynamics {
namespace statics {

constexpr int kUnknowns = 8;  ///< per link: J (3), theta (2), p (3); the equations in the same order
using Vector8 = Eigen::Matrix<double, kUnknowns, 1>;

/// Workspaces sized once per solve: iterate() allocates nothing.
class StaticNewton {
 public:
  explicit StaticNewton(const StaticEquations& eq);

  /// The relative residual of s (static_solver.h's criterion).
  double relativeResidual(const StaticState& s);

  /// Newton from s until the relative residual is below `tolerance` (after at least `min_iterations`) or
  /// `max_iterations` are taken. Returns true when converged; `iterations` counts the iterations taken,
  /// `residual` the last relative residual; `why` says why not.
  bool solve(StaticState& s, double tolerance, int max_iterations, int& iterations, double& residual, std::string& why,
             int min_iterations = 0);

 private:
  /// Link i's residual scaled by F, F l_i and l_i, the moment on the reference basis (3 x 2).
  Vector8 scaled(const StaticState& s, int i);
  /// Sum of squares of the scaled residuals, the moment by its norm (basis-free).
  double merit(const StaticState& s);
  void referenceBases(const StaticState& s);
  void jacobian(StaticState& s);
  void applyStep(const StaticState& from, double alpha, StaticState& to) const;

  const StaticEquations& eq_;
  int m_;
  double force_scale_ = 1.0;  ///< F of the present iterate [N]
  Eigen::Matrix3Xd e1_, e2_;  ///< (3 x m) bases of the planes normal to the iterate's axes
  StaticState trial_;
  BlockTridiagonal<kUnknowns> system_;
  Eigen::Matrix<double, kUnknowns, Eigen::Dynamic> step_;  ///< (8 x m)
  LinkResidual r_;
};

}  // namespace statics
}  // namespace cable_dynamics
