#include "cable_dynamics/simulation/stable_step.h"

#include <array>
#include <cmath>
#include <complex>
#include <algorithm>
#include <limits>
#include <sstream>
#include <vector>

#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/elastic_joints.h"
#include "cable_dynamics/dynamics/seabed_contact.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/params/states.h"

namespace cable_dynamics {
namespace {

/// The recommended step keeps a factor 2 from the limit. The estimate below bounds the linearized
/// system's rates for any state with the bend angles of the kink bound (kinkShare) and the tension bound
/// (tensionBound); what the factor covers: (1) the kink bound is the angle a link's transverse load
/// turns the hanging tension through, so a joint whose tension falls far below it (slack near an ROV)
/// kinks further, and the spin damping grows with sin^2 of half the bend; (2) the velocity terms
/// (gyroscopic, the spin's coupling to the transverse motion) are left out of the linearization; (3)
/// near RK4's real-axis limit a damped mode decays slower than the exact one (R(z) > e^z for z < 0),
/// which the step check's energy balance reads as energy created and retries. Measured against the
/// finite-difference Jacobian and RK4 runs over the ROV's sweep (test_stable_step): rov_tether at 25
/// links recommends 0.46 ms against the truth's 1.74 ms at its sharpest kink (the old estimate: 3.5 ms,
/// twice beyond it), at 100 links 0.48 ms against about 1 ms.
constexpr double kMargin = 2.0;

/// RK4's stability polynomial R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.
std::complex<double> rk4Amplification(std::complex<double> z) {
  return 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
}

/// RK4's reach r(theta): the largest |z| with |R(t z / |z|)| <= 1 for all t <= |z|, on rays at angles
/// theta = 90 ... 180 degrees from the positive real axis, every 0.25 degree. 2.828 on the imaginary
/// axis, 2.785 on the real one, and down to 2.620 at 125 degrees (damping ratio 0.57): a damped
/// oscillation has less room than either axis, which is why a spring and a damper of one mode are
/// taken together (rk4Limit) instead of each against 2.8.
struct Rk4Reach {
  static constexpr int kSteps = 360;
  std::array<double, kSteps + 1> reach{};
  Rk4Reach() {
    for (int i = 0; i <= kSteps; ++i) {
      const double theta = M_PI * (0.5 + 0.5 * i / kSteps);
      const std::complex<double> ray = std::polar(1.0, theta);
      double t = 0.0;
      const double step = 1e-3;
      while (std::abs(rk4Amplification((t + step) * ray)) <= 1.0 + 1e-12) t += step;
      double lo = t, hi = t + step;
      for (int j = 0; j < 50; ++j) {
        const double mid = 0.5 * (lo + hi);
        (std::abs(rk4Amplification(mid * ray)) <= 1.0 + 1e-12 ? lo : hi) = mid;
      }
      reach[i] = lo;
    }
  }
};

/// The largest RK4 step for every mode whose eigenvalues solve lambda^2 + c lambda + k = 0 with
/// 0 <= c <= damping and 0 <= k <= stiffness (rates per unit inertia: [1/s], [1/s^2]). A mode of the
/// linearized chain, I lambda^2 + C lambda + K = 0 with symmetric C, K >= 0, has for its eigenvector v
/// the scalar equation (v*Iv) lambda^2 + (v*Cv) lambda + (v*Kv) = 0: its eigenvalues lie in the set
/// above when damping and stiffness bound the Rayleigh quotients of I^-1 C and I^-1 K (Gershgorin rows
/// below). That set is the left half disc |lambda| <= sqrt(stiffness) cut at Re lambda >= -damping/2
/// (oscillations) and the real segment [-damping, 0] (overdamped); the step must bring each of its
/// rays inside RK4's reach.
double rk4Limit(double damping, double stiffness) {
  static const Rk4Reach table;
  const double infinity = std::numeric_limits<double>::infinity();
  double limit = damping > 0.0 ? table.reach[Rk4Reach::kSteps] / damping : infinity;
  const double omega = std::sqrt(std::max(stiffness, 0.0));
  if (omega == 0.0) return limit;
  limit = std::min(limit, table.reach[0] / omega);  // the imaginary axis: an undamped oscillation
  for (int i = 0; i < Rk4Reach::kSteps; ++i) {
    // The interval [theta_i, theta_i+1]: the smaller reach of its ends against the larger |lambda|
    // (the strip's bound grows towards the real axis); the reach varies by < 0.3 % over 0.25 degree.
    const double theta = M_PI * (0.5 + 0.5 * (i + 1) / Rk4Reach::kSteps);
    const double strip = -std::cos(theta) > 0.0 ? 0.5 * damping / -std::cos(theta) : infinity;
    const double radius = std::min(omega, strip);
    if (radius > 0.0) limit = std::min(limit, std::min(table.reach[i], table.reach[i + 1]) / radius);
  }
  return limit;
}

/// Keeps the mode with the smallest RK4 step and the rate it belongs to.
struct Stiffest {
  double limit = std::numeric_limits<double>::infinity();
  double rate = 0.0;
  std::string mode;
  /// A mode with damping and stiffness rates per unit inertia, [1/s] and [1/s^2] (rk4Limit).
  void consider(double damping, double stiffness, const std::string& name) {
    const double h = rk4Limit(damping, stiffness);
    if (h < limit) {
      limit = h;
      rate = std::max(damping, std::sqrt(std::max(stiffness, 0.0)));  // the largest |lambda| of the set
      mode = name;
    }
  }
  void oscillation(double omega, const std::string& name) { consider(0.0, omega * omega, name); }
  void decay(double rate_, const std::string& name) { consider(rate_, 0.0, name); }
};

/// Fastest speed of a body moving by `motion` [m/s]: the drift plus the oscillation's amplitude
/// times 2 pi / period (the attitude's lever on the offset point left out: small for the presets).
double fastestSpeed(const MotionParams& motion) {
  return motion.velocity.norm() + (motion.period > 0.0 ? motion.amplitude.norm() * 2.0 * M_PI / motion.period : 0.0);
}

/// The implicit integrator's step, for accuracy (StableStep::implicit_recommended): h omega <= kAccuracy for
/// the modes that carry a cable's response and for the motions imposed on its ends, and at most kCap.
/// Continuum estimates over the deployed cable of length L, mass and added mass per length mu, polar
/// inertia per length i_p: the first torsional mode of a rod fixed at the base, (pi / 2L) sqrt(GJ / i_p),
/// and the third bending mode as a taut string under the top tension T plus a cantilever,
/// sqrt((3 pi / L)^2 T / mu + (7.855 / L)^4 EI / mu) (for a hanging chain whose tension falls along it this
/// is about twice the frequency: on the safe side), GJ and EI from the joint springs, k s_k; the base's and
/// a held load's sinusoidal motion, 2 pi / period (25 steps a period).
///
/// kCap = 25 ms, measured (docs/MODEL.md section 6, "The recommended step"): every implicit preset at 25 ms
/// stays within 1 mm (node positions) and 0.5 % of the tension's range of the same run at 2.5 ms over 60 s
/// (rov_tether 3.5 mm over 120 s, ROV sweeping 1.2 m/s), MoorDyn's chains, jumper and tether within 1.1 % of
/// RK4's fairlead tension (bench/README.md). Beyond it the modes left out here take over: the seabed's
/// contact (WD0050 with a 5 m heave: 1.7 % at 50 ms), a stretching line's axial ring.
void recommendImplicitStep(const CableParams& params, const LinkProperties& p, double tension, StableStep& s) {
  constexpr double kAccuracy = 0.25, kCap = 0.025;
  s.implicit_recommended = kCap;
  s.implicit_mode = "the 25 ms cap";
  const auto consider = [&s](double omega, const char* mode) {
    if (omega > 0.0 && kAccuracy / omega < s.implicit_recommended) {
      s.implicit_recommended = kAccuracy / omega;
      s.implicit_mode = mode;
    }
  };
  const auto drive = [](const MotionParams& motion) {
    const bool moves = !motion.amplitude.isZero() || !motion.attitude_amplitude.isZero();
    return moves && motion.period > 0.0 ? 2.0 * M_PI / motion.period : 0.0;
  };
  consider(drive(params.base.motion), "the base's motion");
  if (params.load.mode == LoadMode::kAttached || params.load.mode == LoadMode::kAnchored) {
    consider(drive(params.load.motion), "the load's motion");
  }
  double length = 0.0, mass = 0.0, polar = 0.0, torsion = 0.0, bending = 0.0;
  const int n = p.n;
  for (int k = 0; k < n; ++k) {
    const double l = p.length(k);
    if (l <= 0.0) continue;  // on a winch's drum
    const double arc = length > 0.0 ? 0.5 * (p.length(k - 1) + l) : 0.5 * l;  // the joint's spread (cable_params.cpp)
    length += l;
    mass += p.mass(k) + p.added_mass_per_length(k) * l;
    polar += p.inertia_polar(k);
    torsion = std::max(torsion, p.stiffness_torsion(k) * arc);
    bending = std::max(bending, std::max(p.stiffness_elevation(k), p.stiffness_azimuth(k)) * arc);
  }
  if (length <= 0.0 || params.stiffness.model != StiffnessModel::kBending) return;
  const double mu = mass / length, ip = polar / length;
  consider(ip > 0.0 ? M_PI / (2.0 * length) * std::sqrt(torsion / ip) : 0.0, "the first torsional mode");
  consider(std::sqrt(std::pow(3.0 * M_PI / length, 2) * tension / mu + std::pow(7.855 / length, 4) * bending / mu),
           "the third bending mode");
}

/// The turn a link may make in one RK4 step and stay accurate [rad]. Measured on paper_free_fall_air with
/// a planner that split steps by each link's actual turn: 8 steps still retried at 0.1 rad, 1 at 0.05; the
/// bound below reads the turn from the whole released energy put into the lightest link's spin, at least
/// 1.3 times the actual turn there (0 steps retried at the 0.75 ms it gives, and at 1 ms).
constexpr double kWhipTurn = 0.1;

/// The whip's step (StableStep::whip) for a chain released in air, infinity when the case is not one:
/// in water the drag bounds the flow past the cable (the tension bound's assumption); with an end that
/// moves, a winch or a load held by anything, energy comes in that the configuration does not bound;
/// released in its equilibrium or stretching (an axial spring stores energy that the bound does not
/// follow), it is not taken. The released energy E = V(q0) - min V over the shapes the cable can take:
/// the weights' potential (each mass at most its arc length below the base, as deep as a straight hang)
/// and the joint springs' energy at q0 (ElasticJoints; none left at the minimum, a lower bound on it).
double whipStep(const CableParams& params, const LinkProperties& p, std::string& mode) {
  const double infinity = std::numeric_limits<double>::infinity();
  const bool still = fastestSpeed(params.base.motion) == 0.0 && params.base.motion.attitude_amplitude.isZero();
  if (params.fluid.density > 0.0 || !still || params.winch.enabled || params.load.mode != LoadMode::kFree ||
      params.initial.mode != InitialMode::kAngles || params.stretches()) {
    return infinity;
  }
  const int n = p.n;
  Eigen::VectorXd q, qd;
  initialState(params, q, qd);
  // Depths along the paper's z (down) from the base: link k's axis has z component cos(elevation_k).
  double released = ElasticJoints(p).energy(q), depth = 0.0, arc = 0.0, lightest = infinity;
  for (int k = 0; k < n; ++k) {
    const double l = p.length(k), w = p.gravity * p.submerged_mass(k);
    const double centre_depth = depth + 0.5 * l * std::cos(q(3 * k)), centre_arc = arc + 0.5 * l;
    released += -w * centre_depth + std::abs(w) * centre_arc;  // V(q0) - (its least value)
    depth += l * std::cos(q(3 * k));
    arc += l;
    lightest = std::min(lightest, p.mass(k) * l * l / 12.0);
  }
  for (const LinkAttachment& a : p.attachments) {
    double d = 0.0, s = 0.0;
    for (int k = 0; k < a.link; ++k) {
      d += p.length(k) * std::cos(q(3 * k));
      s += p.length(k);
    }
    const double w = p.gravity * a.submerged_mass;
    released += -w * (d + a.offset * std::cos(q(3 * a.link))) + std::abs(w) * (s + a.offset);
  }
  const double w_load = p.gravity * p.load_submerged_mass;
  released += -w_load * depth + std::abs(w_load) * arc;
  if (!(released > 0.0) || !(lightest > 0.0)) return infinity;
  const double fastest = std::sqrt(2.0 * released / lightest);  // [rad/s]
  std::ostringstream text;
  text << "the whip of a chain released in air: " << released << " J set free, a link turning up to " << fastest
       << " rad/s, " << kWhipTurn << " rad a step";
  mode = text.str();
  return kWhipTurn / fastest;
}

}  // namespace

StableStep estimateStableStep(const CableParams& params, const LinkProperties& p) {
  Stiffest stiffest;
  const int n = p.n;
  // Hanging tension at the top: the submerged weight of everything below; with a winch, of the longest
  // deployment (its per-length weight from the tip link, which never leaves the water). With sections
  // and attachments, floats and heavy parts are counted by magnitude (a float does not lower the tension
  // a heavy part below it puts on the links above: a bound, never an underestimate of a hanging cable's).
  double submerged = p.submerged_mass.cwiseAbs().sum();
  for (const LinkAttachment& a : p.attachments) submerged += std::abs(a.submerged_mass);
  double deployed = 0.0;
  for (int k = 0; k < n; ++k) deployed += std::max(p.length(k), 0.0);
  if (params.winch.enabled) {
    // The longest deployment at the heaviest per-length weight of its sections (no attachments with a winch).
    double per_length = 0.0;
    for (int k = 0; k < n; ++k) {
      if (p.length(k) > 0.0) per_length = std::max(per_length, std::abs(p.submerged_mass(k) / p.length(k)));
    }
    submerged = per_length * params.winch.max_length;
    deployed = std::max(deployed, params.winch.max_length);
  }
  const double hanging = p.gravity * (submerged + std::abs(p.load_submerged_mass));
  // The flow past the cable: the current (its fastest row with a profile) plus the faster end's speed.
  // No point of the cable moves through the water faster than that in the presets' motions, short of a
  // whip; its drag is the transverse load that bends the cable and adds to the tension.
  double current = params.fluid.current.norm();
  for (const Eigen::Vector4d& row : params.fluid.current_profile) current = std::max(current, row.tail<3>().norm());
  const double ends_speed = std::max(fastestSpeed(params.base.motion),
                                     params.load.mode == LoadMode::kAnchored || params.load.mode == LoadMode::kAttached
                                         ? fastestSpeed(params.load.motion)
                                         : 0.0);
  const double flow = params.fluid.density > 0.0 ? current + ends_speed : 0.0;
  // The tension bound: the hanging tension plus the normal drag of the whole deployed length at that
  // flow (and the load's). At rest in a current the drag sets the tension as much as the weight does
  // (rov_tether: 95 N hanging, 384 N of drag at 0.5 m/s), and the ROV's pull raises it (measured 1.2 kN
  // over its sweep; the bound is 4.6 kN): the string modes grow as its square root.
  double drag_load = 0.5 * params.fluid.density * params.load.drag_area * flow * flow;
  double drag_cable = 0.0;
  for (int k = 0; k < n; ++k) {
    if (p.length(k) > 0.0) drag_cable += params.fluid.density * p.drag_normal(k) * p.radius(k) * flow * flow * p.length(k);
  }
  if (params.winch.enabled && deployed > 0.0) drag_cable *= params.winch.max_length / std::max(deployed, 1e-9);
  const double tension = hanging + drag_cable + drag_load;
  const double infinity = std::numeric_limits<double>::infinity();

  // The kink bound (kinkShare): a joint turns the tension through the transverse load of one link, its
  // weight and drag, f l, so tan(beta) <= f l / T with T the hanging tension. An end that imposes its own
  // direction (the clamp, an ROV pulling where it goes) kinks the joint next to it by this too: the
  // rov_tether preset at 25 links (4 m links) bends its last joint by up to 1.34 rad as the ROV sweeps
  // (the bound: 1.1 rad), and by 0.67 rad at 100 links (bound 0.46 rad; within the margin).
  // sin^2(beta / 2) is what a bend damper puts on each link's spin (below).
  std::vector<double> spin_damping(n + 1, 0.0), spin_stiffness(n + 1, 0.0), across_damping(n + 1, 0.0),
      across_stiffness(n + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    const double l = p.length(k);
    if (l <= 0.0) continue;  // on a winch's drum
    const double weight = p.gravity * std::abs(p.submerged_mass(k)) / l;
    const double drag = params.fluid.density * p.drag_normal(k) * p.radius(k) * flow * flow;
    const double beta = hanging > 0.0 ? std::atan((weight + drag) * l / hanging) : 0.5 * M_PI;
    const double share = std::pow(std::sin(0.5 * std::min(beta, 0.5 * M_PI)), 2);
    // Joint k's dampers on the relative angular velocity: the torsion damper about the mean axis of the
    // two links, the bend damper across it. A link bent by beta from that mean axis by beta/2 spins
    // partly across it: the joint damps each link's spin by c_t cos^2(beta/2) + c_b sin^2(beta/2), and
    // the transverse rotation by c_b cos^2 + c_t sin^2 (at most the larger of the two).
    const double c_bend = std::max(p.damping_elevation(k), p.damping_azimuth(k)), c_twist = p.damping_torsion(k);
    // The bend may be anything up to the bound: the largest of that over 0 <= sin^2 <= share.
    spin_damping[k] = c_twist + std::max(c_bend - c_twist, 0.0) * share;
    across_damping[k] = std::max(c_bend, c_twist);
    // The torsion spring's torque is along the mean axis with a unit lever on either link's spin; the
    // bend spring does not turn a link about its own axis.
    spin_stiffness[k] = p.stiffness_torsion(k);
    across_stiffness[k] = std::max(p.stiffness_elevation(k), p.stiffness_azimuth(k));
  }
  // A clamped tip: its bend damper on the last link's spin by the same share, no twist spring (a swivel).
  double tip_spin_damping = 0.0;
  if (n > 0 && (p.tip_clamp_stiffness > 0.0 || p.tip_clamp_damping > 0.0)) {
    tip_spin_damping = p.tip_clamp_damping;  // any angle: the ROV's attitude sets the clamp (a bound)
  }
  const int first = [&] {
    for (int k = 0; k < n; ++k) {
      if (p.length(k) > 0.0) return k;
    }
    return n;
  }();
  for (int k = first; k < n; ++k) {
    const std::string link = std::to_string(k + 1);
    const double l = p.length(k), m = p.mass(k) + p.added_mass_per_length(k) * l;
    // Gershgorin's rows of the joints' damping and stiffness on the link's own rotations: joint k (the
    // base's clamp for the first: no neighbour) and joint k + 1 each add their coefficient on the
    // diagonal and as much to a neighbour; the spin's inertia is the polar one alone (turning a link
    // about its axis moves no other point), the transverse one the link's own about its centre.
    auto row = [&](const std::vector<double>& joint) {
      double r = (k > first ? 2.0 : 1.0) * joint[k];
      if (k + 1 < n) r += 2.0 * joint[k + 1];
      return r;
    };
    const double spin_c = row(spin_damping) + (k == n - 1 ? tip_spin_damping : 0.0), spin_k = row(spin_stiffness);
    stiffest.consider(spin_c / p.inertia_polar(k), spin_k / p.inertia_polar(k),
                      "the spin of link " + link + " (torsion springs, torsion and bend dampers)");
    // Transverse: the bend springs and dampers (the old 4 k / I for uniform joints), the tension's
    // geometric stiffness T l of a link turning about its centre (the zigzag, 12 T / (m l) per unit
    // inertia with the added mass: the beaded string's 4 T / (m l) is for point masses and was a factor
    // 1.6 low for default.yaml), and the linearized drag, rho C_n d |v| per length against the mass and
    // added mass per length.
    const double transverse = p.mass(k) * l * l / 12.0, with_fluid = m * l * l / 12.0;
    const double tip_c = k == n - 1 ? p.tip_clamp_damping : 0.0, tip_k = k == n - 1 ? p.tip_clamp_stiffness : 0.0;
    const double drag = params.fluid.density * 2.0 * p.radius(k) * p.drag_normal(k) * flow / (m / l);
    stiffest.consider((row(across_damping) + tip_c) / transverse + drag,
                      (row(across_stiffness) + tip_k) / transverse + tension * l / with_fluid,
                      "the bending of link " + link + " (bend springs and dampers, tension, drag)");
  }
  if (params.stretches()) {
    // Axial elasticity: the stretch of link k moves everything beyond its far end along its axis, so the
    // axial modes are those of a chain of point masses (link k+1 rigidly between the stretches k and k+1;
    // the load, or the ROV, beyond the last) on springs EA / l and dampers c_a / l. Gershgorin's row of
    // the mass beyond stretch k: 2 (k_k + k_{k+1}) / m, and the same for the dampers, with m the far-end
    // point's m_k / 2 and link k+1's body, m_{k+1} / 2 (all of it when its stretch is locked), or the load.
    const double load_mass = p.load_mass + (params.load.mode == LoadMode::kBody ? 0.0 : params.load.added_mass);
    const bool split = ChainModel::farPoints(params);
    const auto stretches = [&](int k) { return k + 1 < n || load_mass > 0.0; };
    for (int k = first; k < n; ++k) {
      const double l = p.length(k), spring = p.axial_stiffness(k) / l, damper = p.axial_damping / l;
      const bool last = k + 1 == n;
      if (!stretches(k)) continue;  // locked: nothing beyond it (ChainModel::lastStretchLocked)
      const double next_body = last ? load_mass : (split && stretches(k + 1) ? 0.5 : 1.0) * p.mass(k + 1);
      const double beyond = (split ? 0.5 * p.mass(k) : 0.0) + next_body;
      const double next_spring = last ? 0.0 : p.axial_stiffness(k + 1) / p.length(k + 1);
      const double next_damper = last ? 0.0 : p.axial_damping / p.length(k + 1);
      stiffest.consider(2.0 * (damper + next_damper) / beyond, 2.0 * (spring + next_spring) / beyond,
                        "the stretch of link " + std::to_string(k + 1) + " (axial stiffness and damping)");
    }
  }
  if (params.load.mode == LoadMode::kBody) {
    // The ROV body's own modes, each axis on its own: damping (linear, and quadratic at the flow) and the
    // station keeper's gains on the mass plus added mass; the restoring moment (W |r_g - r_b|) in roll and pitch.
    const RovBodyParams& b = params.load.body;
    const double righting = p.gravity * params.load.mass * (b.center_of_gravity - b.center_of_buoyancy).norm();
    for (int axis = 0; axis < 6; ++axis) {
      const bool turn = axis >= 3;
      const double inertia = (turn ? b.inertia(axis - 3, axis - 3) : params.load.mass) + b.added_mass(axis, axis);
      const double damping = b.linear_damping(axis) + b.quadratic_damping(axis) * (turn ? 1.0 : flow) +
                             (turn ? b.rate_gain(axis - 3) : b.velocity_gain(axis));
      const double stiffness = (turn ? b.attitude_gain(axis - 3) + (axis < 5 ? righting : 0.0) : b.position_gain(axis));
      stiffest.consider(damping / inertia, stiffness / inertia, "the ROV body's axis " + std::to_string(axis + 1) +
                                                                    " (damping, station keeping, restoring)");
    }
  }
  // An exact anchor has no spring for RK4 (a constraint force; its drift correction is critically damped at
  // the step itself); the implicit steps' internal hold is folded into their matrix.
  if ((params.load.mode == LoadMode::kAnchored || params.load.mode == LoadMode::kAttached) && n > 0 &&
      !params.load.heldExactly()) {
    const double l = p.length(n - 1);
    const double tip_mass = p.load_mass + params.load.added_mass + 0.5 * (p.mass(n - 1) + p.added_mass_per_length(n - 1) * l);
    stiffest.consider(params.load.coupling_damping / tip_mass, params.load.coupling_stiffness / tip_mass,
                      "the load coupling");
  }
  if (params.seabed.enabled) {
    // The seabed's normal spring-damper on each link's mass per length (omega, damping ratio zeta); and
    // the friction's damper below the regularization speed, mu w' / v_reg per unit mass, with w' the
    // weight per length that presses the link down (its own), and with static friction its anchor
    // spring mu w' / x_b per unit mass.
    const SeabedContactConstants c = makeSeabedContact(params, p);
    const double zeta = params.seabed.damping_ratio;
    for (int k = 0; k < n; ++k) {
      const double l = p.length(k);
      if (l <= 0.0) continue;
      const std::string link = std::to_string(k + 1);
      const double mass = p.mass(k) / l, across = mass + p.added_mass_per_length(k);
      const double omega = std::sqrt(c.stiffness / across);
      stiffest.consider(2.0 * zeta * omega, omega * omega, "the seabed's normal spring under link " + link);
      const double pressing = std::max(p.gravity * p.submerged_mass(k) / l, 0.0);
      const double anchor = c.friction_breakout > 0.0 ? 1.0 / c.friction_breakout : 0.0;  // [1/m]
      stiffest.consider(c.friction_axial * pressing / (c.friction_velocity * mass), c.friction_axial * pressing * anchor / mass,
                        "the seabed's axial friction on link " + link);
      stiffest.consider(c.friction_lateral * pressing / (c.friction_velocity * across),
                        c.friction_lateral * pressing * anchor / across, "the seabed's lateral friction on link " + link);
    }
  }
  StableStep s;
  s.rate = stiffest.rate;
  s.mode = stiffest.mode;
  s.limit = stiffest.limit;
  s.recommended = s.limit < infinity ? s.limit / kMargin : infinity;
  s.whip = whipStep(params, p, s.whip_mode);
  s.recommended = std::min(s.recommended, s.whip);
  recommendImplicitStep(params, p, hanging, s);
  return s;
}

void requireStableTimeStep(const CableParams& params, const LinkProperties& properties) {
  if (params.simulation.integrator != Integrator::kRk4) return;
  const StableStep s = estimateStableStep(params, properties);
  // The message prints the limit to 6 digits, rounded down, so that the step it names is accepted as
  // given (rounded to nearest, a copied 5.45554e-05 was 4e-11 s beyond the 5.455536e-05 s limit).
  if (params.simulation.dt <= s.limit * (1.0 + 1e-9)) return;
  const double magnitude = std::pow(10.0, std::floor(std::log10(s.limit)) - 5.0);
  const double shown = std::floor(s.limit / magnitude) * magnitude;
  std::ostringstream expected;
  expected << "at most " << shown << " s for this cable with integrator rk4 (limited by " << s.mode
           << ", |lambda| = " << s.rate << " 1/s; recommended " << s.recommended
           << " s), or simulation.integrator: implicit (recommended dt " << s.implicit_recommended << " s)";
  std::ostringstream value;
  value << params.simulation.dt;
  throw ConfigError("simulation.dt", value.str(), expected.str());
}

}  // namespace cable_dynamics
