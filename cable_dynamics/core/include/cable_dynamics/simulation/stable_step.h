#pragma once
/// \file
/// \brief The largest time step RK4 is stable at for a cable, from its stiffest mode, and the check
///        that refuses a configuration beyond it (the tools and the node call it at start).

#include <string>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The stiffest mode of a cable and the time steps it allows.
struct StableStep {
  /// RK4's step: the limit with a factor 2 of margin, limit / 2, or the whip's step where that is smaller [s]
  double recommended = 0.0;
  /// A bound for accuracy (infinity where none applies) [s]: a chain released in air from a raised shape
  /// with still ends (nothing damps it and nothing feeds it) whips, each link turning at most at
  /// sqrt(2 E / I) with E the energy its release can free and I the smallest link's inertia about its
  /// centre; RK4's steps stay accurate (the step check's 1e-4 of the energy scale) while each turns by at
  /// most 0.1 rad a step (docs/MODEL.md section 6). paper_free_fall_air: 0.75 ms against the 41 ms that the
  /// stability alone allows, where 54 to 70 of 488 steps needed substeps (issue 27 item 3).
  double whip = 0.0;
  std::string whip_mode;  ///< what sets `whip`, or empty when it is infinity
  double limit = 0.0;        ///< RK4's own limit for the bounded modes: beyond it the limiting mode grows [s]
  double rate = 0.0;         ///< the largest |lambda| of the limiting mode's bound [1/s]
  std::string mode;          ///< which mode, e.g. "the spin of link 3 (torsion springs, torsion and bend dampers)"
  /// simulation.integrator: implicit. Its recursion holds the joint springs and dampers, the drag, the
  /// tension's geometric stiffness, the seabed, a clamped tip and the load coupling implicitly, so no mode
  /// above limits it; its step is chosen for accuracy: h omega <= 0.25 (ROS2's frequency error there,
  /// 0.46 % at rho_inf = 0.9, 0.52 % at 1) for the first torsional mode, the third bending mode and the
  /// ends' imposed motions, and at most 25 ms (measured on the presets: stable_step.cpp) [s].
  double implicit_recommended = 0.0;
  std::string implicit_mode;  ///< the mode or motion that sets it, or "the 25 ms cap"
};

/// Whether `dt` [s] is above the step `bound` [s] as messages print it (6 significant digits, rounded to
/// nearest, so up to 5e-7 of it above): a dt copied from a message is not above the step it names.
inline bool aboveShownStep(double dt, double bound) { return dt > bound * (1.0 + 1e-6); }

/// Bounds each fast mode's eigenvalues as the roots of lambda^2 + c lambda + k = 0 with c and k per
/// unit inertia below Gershgorin's rows, and takes the step that keeps all of them inside RK4's stability
/// region (its reach: 2.83 on the imaginary axis, 2.785 on the real one, 2.62 at 125 degrees): each
/// link's spin (torsion springs; torsion dampers, and the bend dampers through sin^2 of half a kink,
/// the bend bounded by tan(beta) <= f l / T); each link's transverse rotation (bend springs and dampers,
/// the tension's 12 T / (m l), the linearized drag at the current plus the ends' speed); the load
/// coupling; the seabed. The tension is bounded by the hanging weight plus the normal drag of the
/// cable at that flow. docs/MODEL.md section 6. Infinity when nothing is stiff.
StableStep estimateStableStep(const CableParams& params, const LinkProperties& properties);

/// With simulation.integrator rk4, throws ConfigError on simulation.dt when dt exceeds the limit, naming
/// the step the cable needs, the mode that needs it and the alternative (the semi-implicit integrator).
void requireStableTimeStep(const CableParams& params, const LinkProperties& properties);

}  // namespace cable_dynamics
