#pragma once
/// \file
/// \brief The links' axial elasticity (docs/MODEL.md section 12): the law of one link's stretch, its
///        value, its stored energy and its loss, side by side; and the passes over the chain that the
///        dynamics call. A link's far end sits l + s along its axis from its base end: the stretch s [m]
///        is a massless prismatic joint at the link's far end, the tension there is the law below.

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

/// A link shorter than unstretched by more than this share of its length is clearly slack: for the snap
/// counter (CableSimulator::watchStretches) and the implicit step's matrix (linearizeStretches).
constexpr double kClearlySlack = 1e-3;

/// A slack link's chord may shorten to two thirds of its length (the cable between its joints snaking),
/// no further: beyond, its stretch meets a stop as stiff as its spring. Without it a slack link telescoped
/// without limit: config/rov_dive.yaml with EA 1e8 N had its last link at -23 times its length after
/// 300 s (the tether's end 23 links from the ROV it is tied to), and the run ended with exit 0. Why a
/// third: half of the link's mass rides at its far end, m/2 at l + s, and the link's body keeps a second
/// moment of -m l^2/6 about its base (docs/MODEL.md section 12); the link's inertia across its axis,
/// (m/2) (l + s)^2 - m l^2/6 with nothing beyond it, stays positive only for s > -0.42 l.
constexpr double kSlackStop = 1.0 / 3.0;

/// T = k s + c s' while the link is stretched (s > 0), clipped at zero (the damper does not push); 0 while
/// it is slack down to the stop (-l / 3 < s <= 0): a cable carries no compression; beyond the stop
/// (s < -l / 3) T = k (s + l / 3) + c s', clipped at zero from below (the stop pushes, never pulls).
/// k = EA / l [N/m], c = c_a / l [N s/m], l the link's unstretched length [m].
struct AxialSpring {
  /// How far the stretch s [m] is past the stop of a link of length l [m] (< 0 past it).
  static double pastStop(double s, double length) { return s + kSlackStop * length; }
  /// The spring's extension [m]: s while stretched (> 0), s + l / 3 past the stop (< 0), 0 between.
  static double extension(double s, double length) {
    if (s > 0.0) return s;
    const double past = pastStop(s, length);
    return past < 0.0 ? past : 0.0;
  }
  /// The tension [N] at stretch s [m] and rate s' [m/s] (negative: the stop pushes): k e + c s', with the
  /// extension e's sign (the damper never turns a pull into a push, nor the reverse).
  static double tension(double k, double c, double s, double rate, double length) {
    const double e = extension(s, length);
    const double t = k * e + c * rate;
    return e > 0.0 ? (t > 0.0 ? t : 0.0) : e < 0.0 ? (t < 0.0 ? t : 0.0) : 0.0;
  }
  /// The rate [m/s] the damper c = c_a / l reads: l times the strain rate, d/dt (s / l) l = s' - s l' / l.
  /// It is s' but for the winch's link, whose unstretched length l changes at l' (the pay-out speed): a
  /// link paid out at a steady strain grows its stretch, s' = s l' / l, and its damper must not pull.
  static double dampedRate(double s, double rate, double length, double length_rate) {
    return length_rate != 0.0 && length > 0.0 ? rate - s * length_rate / length : rate;
  }
  /// Strain energy 1/2 k e^2 [J] (1/2 k s^2 while stretched, 1/2 k (s + l / 3)^2 past the stop, 0
  /// between): the tension's elastic part has this potential.
  static double energy(double k, double s, double length) {
    const double e = extension(s, length);
    return 0.5 * k * e * e;
  }
  /// The energy's rate with the unstretched length l at a fixed s [J/m], for k = EA / l:
  /// d/dl (EA e^2 / (2 l)) = -E / l + k e de/dl, with de/dl = kSlackStop past the stop, 0 otherwise.
  static double energyPerLength(double k, double s, double length) {
    const double e = extension(s, length);
    return -0.5 * k * e * e / length + (e < 0.0 ? k * e * kSlackStop : 0.0);
  }
  /// The power the tension T takes out beyond the energy it stores [W], >= 0: (T - k e) s' (c s'^2 when
  /// not clipped; 0 between stretched and the stop).
  static double loss(double k, double s, double rate, double tension, double length) {
    return (tension - k * extension(s, length)) * rate;
  }
};

/// Each link's stretch and rate from the state x into the link blocks, and the tension and loss of the
/// law above (zeros with rigid links, whose blocks keep zeros); `winch_speed` [m/s] the rate of the first
/// link's unstretched length (0 without a winch). O(n), no allocation.
void computeAxialTensions(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, double winch_speed);

/// The strain energy of every link's stretch at the stretches in `data` [J].
double axialEnergy(const ChainModel& model, const ChainData& data);

/// What a winch paying out at `winch_speed` [m/s] changes in the strain energy at fixed stretches [W]:
/// the winch's link's stiffness EA / l falls as its unstretched length l grows, so the same stretch s
/// holds less energy, 1/2 EA s^2 / l; its rate at fixed s, -v (1/2 EA s^2 / l) / l, is an input to the
/// energy balance as the paid-out material's own energy is (docs/MODEL.md section 12, "With a winch").
double winchStrainPower(const ChainData& data, double winch_speed);

/// The power the stretches' dampers take out [W] with each link's stretch rate (and the rate its damper
/// reads) shifted by shift(k) [m/s] (n entries), the stretches as they are. The implicit step books its
/// stages' losses with it, at the rates its matrix solved the dampers at (as the seabed's,
/// seabedContactDissipation): at the stage's start rate a damper with h c / m of several over-counts.
double axialLossAtShiftedRates(const ChainModel& model, const ChainData& data, const Eigen::VectorXd& shift);

/// The power the stretches' dampers take out [W], >= 0.
double axialLoss(const ChainModel& model, const ChainData& data);

}  // namespace cable_dynamics
