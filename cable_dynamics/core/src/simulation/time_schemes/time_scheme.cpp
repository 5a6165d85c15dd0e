#include "cable_dynamics/simulation/time_schemes/time_scheme.h"

#include "cable_dynamics/simulation/time_schemes/linear_implicit.h"
#include "cable_dynamics/simulation/time_schemes/rk4.h"
#include "cable_dynamics/simulation/time_schemes/semi_implicit.h"

namespace cable_dynamics {

bool TimeScheme::evaluateEnd(ChainDynamics& dynamics, const EndInputs& ends, const Eigen::VectorXd& x) {
  // Schemes that reuse nothing evaluate only what the energy check reads.
  double magnitude = 0.0;
  dynamics.mechanicalEnergy(x, ends, magnitude);
  return true;
}

std::unique_ptr<TimeScheme> makeTimeScheme(Integrator integrator, int links, double rho_infinity, bool body,
                                           bool axial) {
  switch (integrator) {
    case Integrator::kRk4:
      return std::make_unique<Rk4Scheme>(StateLayout::size(links, body, axial));
    case Integrator::kSemiImplicit:
      return std::make_unique<SemiImplicitScheme>(links, body);
    case Integrator::kImplicit:
      return std::make_unique<LinearImplicitScheme>(links, rho_infinity, body, axial);
  }
  return nullptr;
}

}  // namespace cable_dynamics
