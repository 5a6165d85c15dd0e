#pragma once
// Starting guesses of the static solver: the limp chain swept from the tip, the tip force that makes
// it meet a coupling spring (shooting), the straight cable along the clamp. Internal to the statics.

#include <string>

#include <Eigen/Core>

#include "static_equations.h"

namespace cable_dynamics {
namespace statics {

/// Every link along `direction` (unit) from the base; forces from the tip (forcesForAxes).
void straightStart(const StaticEquations& eq, const Eigen::Vector3d& direction, StaticState& s);

/// Keeps the axes; sets the base ends from the base outwards and the forces J_i from the tip inwards
/// so that closure and force balance hold exactly.
void forcesForAxes(const StaticEquations& eq, StaticState& s);

/// The limp chain in equilibrium from the tip: with `pull` the coupling force on the load [N] (zero for
/// a free tip), each link along the force it carries, u_i || N_i(u_i) - l_i J_{i+1} (a fixed point per
/// link, the drag depending on the direction), J_i = J_{i+1} - F_i. Exact without springs in a uniform
/// current; with a depth profile the passes repeat with the last pass's depths. s's axes are the
/// fixed points' first guesses and its base ends the depths of the first pass.
void sweepLimp(const StaticEquations& eq, const Eigen::Vector3d& pull, StaticState& s);

/// The limp chain whose tip meets the coupling spring: Newton on the pull P [N] (3 unknowns, central
/// differences of sweepLimp) for tip(P) - target + P / k_c = 0. Returns false, with `why`, when it
/// does not converge; s holds the best sweep found either way.
bool shootCoupled(const StaticEquations& eq, StaticState& s, std::string& why);

}  // namespace statics
}  // namespace cable_dynamics
