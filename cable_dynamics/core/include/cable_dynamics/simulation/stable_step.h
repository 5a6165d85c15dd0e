#pragma once
/// \file
/// \brief The largest time step RK4 is stable at for a cable, from its stiffest mode, and the check
///        that refuses a configuration beyond it (the tools and the node call it at start).

#include <string>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The stiffest mode of a cable and the time steps it allows.
struct StableStep {
  double recommended = 0.0;  ///< RK4 with a factor 2 of margin, 1.4 / |lambda| [s]
  double limit = 0.0;        ///< RK4's own limit, 2.8 / |lambda|: beyond it the stiffest mode grows [s]
  double rate = 0.0;         ///< |lambda| of the stiffest mode [1/s]
  std::string mode;          ///< which mode, e.g. "the bend damper of joint 3"
  /// simulation.integrator: implicit. Its recursion holds the joint springs and dampers, the drag, the
  /// tension's geometric stiffness and the load coupling implicitly, so no mode above limits it; its step
  /// is chosen for accuracy: h omega <= 0.25 (the implicit midpoint's frequency error (h omega)^2 / 12,
  /// 0.5 %) for the first torsional mode and the third bending mode, and at most 10 ms [s].
  double implicit_recommended = 0.0;
  std::string implicit_mode;  ///< the mode that sets it, or "the 10 ms cap"
};

/// Estimates |lambda| of each fast mode and takes the largest: the highest string mode of each link
/// under the hanging tension, 2 sqrt(T / (m l)); each joint spring against the inertia it turns,
/// sqrt(4 k / I); each joint damper, 4 c / I (the relative motion of neighbours doubles the rate
/// twice over); the load coupling, sqrt(k_c / m_tip) and c_c / m_tip, with m_tip the load's mass and
/// added mass plus half the last link's. RK4's stability region reaches 2.8 along the imaginary axis
/// (oscillations) and 2.78 along the negative real axis (damping). Infinity when nothing is stiff.
StableStep estimateStableStep(const CableParams& params, const LinkProperties& properties);

/// With simulation.integrator rk4, throws ConfigError on simulation.dt when dt exceeds the limit, naming
/// the step the cable needs, the mode that needs it and the alternative (the semi-implicit integrator).
void requireStableTimeStep(const CableParams& params, const LinkProperties& properties);

}  // namespace cable_dynamics
