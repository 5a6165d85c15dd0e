#pragma once
/// \file
/// \brief Neighbouring links cannot pass through each other: the fold stop of a bending-model joint
///        (docs/MODEL.md section 5), its value, energy and tangent stiffness side by side.
///
/// Why: a limp cable (no bend spring) paid out onto the bottom piles up, and its links fold flat onto
/// their neighbours; nothing kept a joint's bend below pi, and at pi the joint's geometry is singular (the
/// mean axis (prev + axis) / (1 + cos beta) of the twist spring's torque, the dampers' direction, and the
/// transport holonomy, which jumps by 2 pi as one link sweeps through the other). A limp tether in a
/// current diverged there (issue 27 item 4: "energy created" at 4.1 s with a torsion spring, a non-finite
/// damper direction at 13.7 s without). A real cable cannot fold through itself: two links sharing an end
/// touch when the longer one's far end meets the other, at a bend of pi - asin(d / l), or sooner (kFinestFold).
///
/// The stop is a barrier on the bend beyond that angle beta_s, with s = (beta - beta_s) / (pi - beta_s):
///   V = k (pi - beta_s)^2 (-s - ln(1 - s)),  dV/dbeta = k (beta - beta_s) / (1 - s),  d2V/dbeta2 = k / (1 - s)^2,
/// a spring of stiffness k where it engages that stiffens without bound towards pi, so no impact passes
/// it. Its stiffness is the geometric stiffness T l of the hanging tension T (the weight of everything
/// below the base) across a link of length l: a fold carries no tension (a hairpin under tension opens),
/// so the stop takes the place of the tension's stiffness that the RK4 step estimate bounds for every
/// joint (stable_step.cpp), instead of adding a faster mode. Conservative: its energy is in the elastic
/// energy, its power in the springs'.
///
/// The bend damper and the twist spring act on an engaged joint as on any other; the mean axis stays
/// defined because the bend stays below pi. The paper's stiffness model has no stop (its absolute angles
/// are singular at the vertical already, docs/MODEL.md section 5). The paper formulation's ElasticJoints
/// has it too, with automatic differentiation (energyOf).

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// One joint's fold stop.
struct FoldStop {
  /// The least room the stop leaves below pi [rad]. A joint's bend stands for the cable's curvature over a
  /// link, so a fold tighter than the link's scale is not resolved anyway; where the links would touch
  /// closer to pi (thin cables, long links: 0.02 rad for 2 cm on 1 m), the barrier would have to absorb a
  /// folding link's energy within that sliver, a mode faster than the fold by 1 / room, and the twist's
  /// lever 1 / sin(room / 2) would reach 100. At 0.25 rad the lever is below 8 and the limp tether's
  /// piling runs without a retried step at 1 ms (test_fold_stop).
  static constexpr double kFinestFold = 0.25;

  double angle = M_PI;     ///< the bend at which the links touch, beta_s [rad]
  double stiffness = 0.0;  ///< k where it engages [N m / rad]

  /// The stop of a joint between links of lengths `l_prev` and `l` [m] of outer diameter `diameter` [m],
  /// under the hanging tension `tension` [N]. The longer link's reach sets the angle: a winch's growing
  /// first link, shorter than the cable is thick, would otherwise stop at a right angle.
  static FoldStop between(double l_prev, double l, double diameter, double tension) {
    const double reach = std::max(l_prev, l);
    FoldStop s;
    if (!(reach > 0.0) || !(tension > 0.0)) return s;  // no tension, no stop (k = 0): as before
    s.angle = M_PI - std::max(std::asin(std::min(diameter / reach, 1.0)), kFinestFold);
    s.stiffness = tension * reach;
    return s;
  }

  /// The stop of joint k (between links k-1 and k, k >= 1) at the lengths and radii of `p`.
  static FoldStop ofJoint(const LinkProperties& p, int k, double tension) {
    return between(p.length(k - 1), p.length(k), 2.0 * std::max(p.radius(k - 1), p.radius(k)), tension);
  }

  bool engaged(double bend) const { return stiffness > 0.0 && bend > angle; }

  /// Share s of the room left between the stop and pi, kept below 1 (a bend at pi to round-off).
  double share(double bend) const { return std::min((bend - angle) / (M_PI - angle), 1.0 - 1e-12); }

  /// V [J]; 0 where it is not engaged.
  double energy(double bend) const { return energyOf(bend, bend); }

  /// V for a scalar S with automatic differentiation (ElasticJoints), `value` the bend's value [J].
  template <typename S>
  S energyOf(const S& bend, double value) const {
    using std::log;
    if (!engaged(value)) return S(0.0);
    const double room = M_PI - angle;
    const S s = value - angle < (1.0 - 1e-12) * room ? S((bend - angle) / room) : S(1.0 - 1e-12);
    return stiffness * room * room * (-s - log(1.0 - s));
  }

  /// The hanging tension that sizes every joint's stop [N]: g times the magnitudes of the submerged masses
  /// of the links (slots as configured), the attachments and the load.
  static double tensionOf(const LinkProperties& p) {
    double submerged = p.submerged_mass.cwiseAbs().sum() + std::abs(p.load_submerged_mass);
    for (const LinkAttachment& a : p.attachments) submerged += std::abs(a.submerged_mass);
    return p.gravity * submerged;
  }

  /// dV/dbeta [N m].
  double moment(double bend) const { return engaged(bend) ? stiffness * (bend - angle) / (1.0 - share(bend)) : 0.0; }

  /// d2V/dbeta2 [N m / rad]: the implicit step's tangent across the joint.
  double tangent(double bend) const {
    if (!engaged(bend)) return 0.0;
    const double rest = 1.0 - share(bend);
    return stiffness / (rest * rest);
  }

  /// Its torque on the body of `axis` for the joint (prev, axis) with bend angle `bend`, sine its sine and
  /// cross = prev x axis: -dV/dbeta (prev x axis) / sin(beta) [N m] (the body of `prev` gets the opposite),
  /// as the bend spring's (forces/joint_springs.h). Zero at a bend of pi exactly, where no direction is
  /// defined.
  Eigen::Vector3d torque(double bend, double sine, const Eigen::Vector3d& cross) const {
    if (!engaged(bend) || !(sine > 0.0)) return Eigen::Vector3d::Zero();
    return -moment(bend) / sine * cross;
  }
};

}  // namespace cable_dynamics
