// The links' axial elasticity (cable.axial_stiffness, docs/MODEL.md section 12) against closed forms nobody
// here wrote: the longitudinal modes of a hanging rod with a tip mass (beta tan(beta) = rod mass / tip
// mass), the peak tension of a mass snapping a slack line taut (W (1 + sqrt(1 + 2 k h / W))), Irvine's
// elastic catenary between two points; and the energy balance with the strain energy in it.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/state_layout.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "reference/grounded_catenary.h"

using namespace cable_dynamics;

namespace {

/// log2 of successive error ratios: the observed order of convergence when n doubles.
double order(double coarse, double fine) { return std::log2(std::abs(coarse / fine)); }

/// The root of beta tan(beta) = ratio in ((m - 1) pi, (m - 1/2) pi) for mode m = 1, 2, ... (bisection).
double longitudinalRoot(double ratio, int mode) {
  double lo = (mode - 1) * M_PI + 1e-12, hi = (mode - 0.5) * M_PI - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tan(mid) < ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Mean period of a signal from its upward zero crossings (linear interpolation between samples) [s].
double meanPeriod(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (y[i - 1] < 0.0 && y[i] >= 0.0) crossings.push_back(t[i - 1] - y[i - 1] * (t[i] - t[i - 1]) / (y[i] - y[i - 1]));
  }
  if (crossings.size() < 2) return NAN;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

constexpr double kRodLength = 10.0;        // [m]
constexpr double kRodMassPerLength = 1.0;  // [kg/m]
constexpr double kRodStiffness = 1.0e5;    // EA [N]
constexpr double kTipMass = 10.0;          // [kg]

std::string formatDt(double dt) {
  std::ostringstream out;
  out << std::setprecision(17) << dt;
  return out.str();
}

/// A rod hanging straight down in air, at its elastic equilibrium under gravity, a tip mass at its end.
CableParams hangingRod(int n, double dt) {
  return loadConfigString(
      "cable: {links: " + std::to_string(n) + ", length: 10.0, diameter: 0.02, mass_per_length: 1.0, "
      "axial_stiffness: 1.0e5, stiffness: {model: bending}}\n"
      "load: {mass: 10.0, mode: free}\nfluid: {density: 0.0}\ninitial: {mode: equilibrium}\n"
      "simulation: {integrator: rk4, dt: " + formatDt(dt) + "}\n");
}

/// The angular frequency of the rod's longitudinal mode `mode`, simulated: from its elastic equilibrium,
/// every stretch is displaced along the continuum mode's strain, cos(beta x / L), by 1e-4 of the static
/// stretch scale, and the tip's displacement along the rod is timed over `periods` of the mode [rad/s].
double simulatedLongitudinalFrequency(int n, double beta, int periods) {
  const double omega = beta * std::sqrt(kRodStiffness / kRodMassPerLength) / kRodLength;
  // RK4's phase error (omega dt)^4 / 120 at 400 steps a period: 1e-8; and within its stability limit
  // for the link's own axial mode, 1.4 l / c.
  const double wave = std::sqrt(kRodStiffness / kRodMassPerLength);  // c [m/s]
  const double dt = std::min(2.0 * M_PI / omega / 400.0, 0.5 * kRodLength / n / wave);
  CableSimulator sim(hangingRod(n, dt));
  Eigen::VectorXd x = sim.state();
  const double l = kRodLength / n, amplitude = 1e-6;  // stretch per link [m]: the static one is 1e-4 .. 2e-4
  for (int k = 0; k < n; ++k) {
    const double at = (k + 0.5) * l;  // link k's spring spans it: the continuum's strain at its middle
    x(StateLayout::stretch(n, false, k)) += amplitude * std::cos(beta * at / kRodLength);
  }
  sim.setState(x);
  SimulationSnapshot s;
  sim.snapshot(s);
  std::vector<double> t, tip;
  const int steps = static_cast<int>(periods * 2.0 * M_PI / omega / dt);
  double rest = 0.0;
  for (int i = 0; i <= steps; ++i) {
    sim.snapshot(s);
    const double z = s.chain.ends(2, n);
    if (i == 0) rest = z;
    t.push_back(sim.time());
    tip.push_back(z - rest);
    if (i < steps) {
      EXPECT_TRUE(sim.step().ok);
    }
  }
  // The mean of the displacement over whole periods is the equilibrium's: subtract it.
  double mean = 0.0;
  for (double v : tip) mean += v;
  mean /= static_cast<double>(tip.size());
  for (double& v : tip) v -= mean;
  return 2.0 * M_PI / meanPeriod(t, tip);
}

}  // namespace

TEST(AxialElasticity, HangingRodRingsAtItsLongitudinalFrequencies) {
  // Rod mass 10 kg = tip mass: beta tan(beta) = 1, beta_1 = 0.8603, beta_2 = 3.4256; omega = beta c / L
  // with c = sqrt(EA / m') = 316 m/s (27.21 and 108.3 rad/s). Gravity preloads the rod (static strain up
  // to 2e-3) but the law is linear while taut, so the modes are those without it.
  const double ratio = kRodMassPerLength * kRodLength / kTipMass;
  for (int mode : {1, 2}) {
    const double beta = longitudinalRoot(ratio, mode);
    const double exact = beta * std::sqrt(kRodStiffness / kRodMassPerLength) / kRodLength;
    std::vector<double> errors;
    for (int n : {50, 100, 200}) {
      const double omega = simulatedLongitudinalFrequency(n, beta, 12);
      errors.push_back(omega / exact - 1.0);
      std::cout << "mode " << mode << " n = " << n << ": omega " << std::setprecision(8) << omega << " rad/s, exact "
                << exact << ", error " << std::setprecision(3) << errors.back() << "\n";
    }
    std::cout << "  order in n: " << order(errors[0], errors[1]) << ", " << order(errors[1], errors[2]) << "\n";
    // Measured (mode 1 / mode 2): -2.13e-5 / -2.22e-4 at n = 50, -5.33e-6 / -5.55e-5 at 100, -1.33e-6 /
    // -1.39e-5 at 200: second order in 1/n (observed orders 2.00 and 2.00 for both modes). Half of each
    // link's mass rides beyond its stretch, so every node between two springs carries half of each
    // neighbouring link, as a centred lumping does (docs/MODEL.md section 12); the frequencies come out
    // low by the lumping's (omega l / c)^2 / 24. With every link's mass at its base end (until session 28)
    // they came out high at first order: +0.365 / +0.189 % at n = 50. Bounds: 5x each mode's measured
    // error at n = 50 and 200 (mode 1: 1e-4 and 7e-6; mode 2: 1.1e-3 and 7e-5), and the order within
    // [1.8, 2.2] (1.0 would be the old lumping).
    const double at_50 = mode == 1 ? 1e-4 : 1.1e-3, at_200 = mode == 1 ? 7e-6 : 7e-5;
    EXPECT_LT(std::abs(errors[0]), at_50) << "mode " << mode;
    EXPECT_LT(std::abs(errors[2]), at_200) << "mode " << mode;
    EXPECT_NEAR(order(errors[0], errors[1]), 2.0, 0.2) << "mode " << mode;
    EXPECT_NEAR(order(errors[1], errors[2]), 2.0, 0.2) << "mode " << mode;
  }
}

namespace {

/// How slack the snap case's line starts [m]: its first link's stretch, within the slack stop (-l/3) of
/// the ten-link lines' 1 m links.
constexpr double kSnapSlack = 0.3;

/// The snap case below: n links of a 10 m line of `mass_per_length` [kg/m] holding 100 kg, at `integrator`
/// and `dt` [s].
CableParams snapLine(int n, const std::string& integrator, double dt, double mass_per_length) {
  std::ostringstream config;
  config << "cable: {links: " << n << ", length: 10.0, diameter: 0.01, mass_per_length: " << mass_per_length
         << ", axial_stiffness: 1.0e5, "
            "stiffness: {model: bending}}\nload: {mass: 100.0, mode: free}\nfluid: {density: 0.0}\n"
            "initial: {elevation: 0.0, azimuth: 0.0, torsion: 0.0}\nsimulation: {integrator: "
         << integrator << ", dt: " << std::setprecision(17) << dt << "}\n";
  return loadConfigString(config.str());
}

/// The snap case below with n links at `integrator` and `dt`: the peak tension at the base [N] and the
/// snaps counted.
double snapPeak(int n, const std::string& integrator, double dt, long& snaps, double& largest,
                double mass_per_length = 1.0e-4, long* retried = nullptr) {
  CableSimulator sim(snapLine(n, integrator, dt, mass_per_length));
  Eigen::VectorXd x = sim.state();
  x(StateLayout::stretch(n, false, 0)) = -kSnapSlack;
  sim.setState(x);
  SimulationSnapshot s;
  double peak = 0.0;
  for (int i = 0, steps = static_cast<int>(std::lround(0.7 / dt)); i < steps; ++i) {
    EXPECT_TRUE(sim.step().ok);
    sim.snapshot(s);
    peak = std::max(peak, s.chain.tension(0));
  }
  snaps = sim.snaps();
  largest = sim.largestTension();
  if (retried != nullptr) *retried = sim.retriedSteps();
  return peak;
}

}  // namespace

TEST(AxialElasticity, ASnapOntoASlackLinePeaksAtTheEnergyBound) {
  // A 100 kg mass hangs in air on a 10 m line (EA 1e5 N: k = EA / L = 1e4 N/m) of 1 g, 1e-5 of the mass:
  // the line is slack by h = 0.3 m (its first link's stretch at -h), so the mass falls h and snaps it
  // taut. With a massless line the peak tension is W (1 + sqrt(1 + 2 k h / W)) = 3598 N (energy: W (h +
  // d) = k d^2 / 2). RK4 at 0.02 ms, the implicit step at 10 ms (far beyond what it recommends for the
  // ten-link lines: 85 us at 1e-4 kg/m, 0.85 ms at 0.01 kg/m) and at its recommended step, the tension at
  // the base sampled every step.
  const double h = kSnapSlack, k = 1.0e5 / 10.0, weight = 100.0 * 9.81;
  const double exact = weight * (1.0 + std::sqrt(1.0 + 2.0 * k * h / weight));
  long snaps = 0;
  double largest = 0.0;
  const double rk4 = snapPeak(10, "rk4", 2e-5, snaps, largest);
  std::cout << "snap, RK4: peak " << rk4 << " N, closed form " << exact << " N, error " << rk4 / exact - 1.0 << "\n";
  // What the closed form leaves out is the line's own mass: the snap sends a wave down it whose stress is
  // v sqrt(EA m') (v = sqrt(2 g h) = 3.13 m/s: 31 N here, 0.7 %), and it rings on the links' own axial mode.
  // With 0.01 kg/m (wave stress 99 N) the peak was 1.79 % above. Measured: +0.123 %. Bound: the 2 % (16x).
  EXPECT_NEAR(rk4 / exact, 1.0, 2e-2);
  // The first link went from slack to taut once (the mass rebounds into free flight at 0.64 s and is
  // still rising at 0.7 s, the end of the run; at 0.79 s the light line's rattle snaps it taut again); the
  // others started at s = 0, not slack. The simulator's own largest tension
  // (at the steps' ends, of the stretches' law) is the peak at the far end of the first link.
  EXPECT_EQ(snaps, 1);
  EXPECT_NEAR(largest, rk4, 1e-3 * rk4);
  // The implicit step, on one link: the mass on the line's spring alone.
  const double implicit = snapPeak(1, "implicit", 0.01, snaps, largest);
  std::cout << "snap, implicit at 10 ms, one link: peak " << implicit << " N, error " << implicit / exact - 1.0 << "\n";
  // Measured: -0.092 %. Bound 0.5 % (5.4x).
  EXPECT_NEAR(implicit / exact, 1.0, 5e-3);
  EXPECT_EQ(snaps, 1);
  // On ten links of a light tether (0.01 kg/m: its links' own axial modes at h omega = 30 at 10 ms) the
  // linearly implicit step puts energy in where a link's stiff spring switches on within the step; the
  // step's energy check (2e-3 of the scale in one step, docs/MODEL.md section 6) retries that step in
  // pieces, and the run goes on (before that check it diverged after the snap). Measured: -0.28 % of the
  // closed form (+0.19 % with every link's mass at its base end, +0.04 % in session 23's code), one step retried; RK4 at 0.02 ms gives +1.85 %, the line's wave stress v sqrt(EA m') that
  // 10 ms does not resolve (1 ms a link for the wave). With 1e-4 kg/m (h omega = 300) at 10 ms the snap's
  // step is refused even in 64 pieces (the state kept, the failure reported: docs/MODEL.md section 12,
  // "Limits"); at its recommended step it holds (below). Bound: the 2 % (50x; 1.1x of RK4's).
  long retried = 0;
  const double light = snapPeak(10, "implicit", 0.01, snaps, largest, 0.01, &retried);
  std::cout << "snap, implicit at 10 ms, ten links of 0.01 kg/m: peak " << light << " N, error " << light / exact - 1.0
            << ", " << retried << " steps retried\n";
  EXPECT_NEAR(light / exact, 1.0, 2e-2);
  EXPECT_LE(retried, 3);
  // The "with the implicit step at its recommended dt": the step the implicit integrator recommends
  // for the ten links of 1e-4 kg/m (estimateStableStep, 85 us; the links' axial modes at h omega = 2.7
  // there, left to the step's damping) follows the snap with no step retried. Measured +0.012 % of the massless closed form: the line's wave stress (0.23 %,
  // which RK4 at 0.02 ms resolves, +0.2 % above) is damped out. Bound 0.1 % (5x).
  const CableParams ten = snapLine(10, "implicit", 0.01, 1.0e-4);
  const double recommended = estimateStableStep(ten, deriveLinkProperties(ten)).implicit_recommended;
  const double at_recommended = snapPeak(10, "implicit", recommended, snaps, largest, 1.0e-4, &retried);
  std::cout << "snap, implicit at its recommended " << recommended * 1e3 << " ms, ten links of 1e-4 kg/m: peak "
            << at_recommended << " N, error " << at_recommended / exact - 1.0 << ", " << retried << " steps retried\n";
  EXPECT_GT(recommended, 5e-5);  // not RK4's 22 us: the implicit step's own recommendation
  EXPECT_NEAR(at_recommended / exact, 1.0, 1e-3);
  EXPECT_EQ(retried, 0);
  EXPECT_EQ(snaps, 1);
}

TEST(AxialElasticity, EnergyIsConservedWithTheStrainEnergyAndBalancedWithItsDamper) {
  // An elastic pendulum: 8 links, 8 m, 1 kg/m, EA 2e4 N, a 5 kg tip mass, in air, from its elastic
  // equilibrium hanging down (strain up to 0.6 %) swung about the base at 0.5 rad/s (it rises to about 26
  // degrees): every link stays taut, so the tension law is smooth along the run. Without dampers the energy
  // (kinetic + potential + joint and axial strain) is constant up to RK4's error, which falls at fourth
  // order in dt; with an axial damper (c_a 200 N s) the balance with the dissipated energy holds the same
  // way, and the damper has taken energy out.
  const int n = 8;
  auto run = [n](double dt, double damping, double& dissipated, const char* integrator = "rk4") {
    std::ostringstream config;
    config << "cable: {links: 8, length: 8.0, diameter: 0.02, mass_per_length: 1.0, axial_stiffness: 2.0e4, "
              "axial_damping: "
           << damping << ", stiffness: {model: bending}}\nload: {mass: 5.0, mode: free}\nfluid: {density: 0.0}\n"
           << "initial: {mode: equilibrium}\nsimulation: {integrator: " << integrator << ", dt: " << std::setprecision(17)
           << dt << "}\n";
    CableSimulator sim(loadConfigString(config.str()));
    Eigen::VectorXd x = sim.state();
    for (int k = 0; k < n; ++k) x(StateLayout::omega(k) + 1) = 0.5;  // a rigid turn about the base [rad/s]
    sim.setState(x);
    SimulationSnapshot s;
    sim.snapshot(s);
    // The scale: the cable's and the mass's weight times the length, 1020 J.
    const double start = s.total_energy, scale = (8.0 + 5.0) * 9.81 * 8.0;
    double worst = 0.0, slack = 0.0;
    const int steps = static_cast<int>(std::lround(3.0 / dt));
    for (int i = 0; i < steps; ++i) {
      EXPECT_TRUE(sim.step().ok);
      sim.snapshot(s);
      worst = std::max(worst, std::abs(s.total_energy - start) / scale);
      slack = std::min(slack, s.chain.stretch.minCoeff());
    }
    EXPECT_GE(slack, 0.0) << "a link went slack: the run is not the smooth one this test is about";
    dissipated = s.dissipated_energy;
    return worst;
  };
  double dissipated = 0.0;
  const double coarse = run(4e-3, 0.0, dissipated), fine = run(2e-3, 0.0, dissipated);
  EXPECT_EQ(dissipated, 0.0);
  const double damped = run(2e-3, 200.0, dissipated);
  std::cout << "energy drift (relative to 1020 J): " << coarse << " at 4 ms, " << fine << " at 2 ms (order "
            << order(coarse, fine) << "); with the damper " << damped << ", dissipated " << dissipated << " J\n";
  // Measured: 1.6e-10 at 4 ms, 8.9e-12 at 2 ms (order 4.2: RK4's, the axial modes at omega dt = 0.57 at
  // 2 ms); with the damper 1.9e-12 and 0.051 J dissipated. Bounds: 5e-11 (5.6x), order within [3.5, 5],
  // 1e-11 with the damper (5x), and at least 0.01 J taken out (the damper's rate itself:
  // AnAxialDamperDecaysAtItsRate).
  EXPECT_LT(fine, 5e-11);
  EXPECT_GT(order(coarse, fine), 3.5);
  EXPECT_LT(order(coarse, fine), 5.0);
  EXPECT_LT(damped, 1e-11);
  EXPECT_GT(dissipated, 0.01);
  // The implicit step (ROS2): its balance closes at second order (the stages' powers, trapezoidal).
  const double implicit_coarse = run(0.01, 0.0, dissipated, "implicit");
  const double implicit_fine = run(0.005, 0.0, dissipated, "implicit");
  std::cout << "implicit: energy balance " << implicit_coarse << " at 10 ms, " << implicit_fine << " at 5 ms (order "
            << order(implicit_coarse, implicit_fine) << ")\n";
  // Measured: 8.1e-7 at 10 ms, 2.0e-7 at 5 ms (order 2.03). Bounds: 5e-6 at 10 ms (6x), order above 1.7.
  EXPECT_LT(implicit_coarse, 5e-6);
  EXPECT_GT(order(implicit_coarse, implicit_fine), 1.7);
}

TEST(AxialElasticity, AnAxialDamperDecaysAtItsRate) {
  // One link (5 m, 5 kg, EA 1e6 N, c_a 5e3 N s) holding a 50 kg mass in air: the link hangs from the base,
  // so the mass on its stretch (the load and the link's far-end half, 52.5 kg) is an oscillator with
  // k = EA / l = 2e5 N/m and c = c_a / l = 1e3 N s/m: from a displaced equilibrium it rings at
  // omega_d = sqrt(k / m - (c / 2m)^2) = 61.5 rad/s, its amplitude
  // decaying as exp(-c t / 2m) (damping ratio 0.16: taut throughout, since the static stretch, 2.5 mm,
  // exceeds the 1 mm it is displaced by).
  CableSimulator sim(loadConfigString(
      "cable: {links: 1, length: 5.0, diameter: 0.02, mass_per_length: 1.0, axial_stiffness: 1.0e6, "
      "axial_damping: 5.0e3, stiffness: {model: bending}}\nload: {mass: 50.0, mode: free}\nfluid: {density: 0.0}\n"
      "initial: {mode: equilibrium}\nsimulation: {integrator: rk4, dt: 0.001}\n"));
  Eigen::VectorXd x = sim.state();
  const double rest = x(StateLayout::stretch(1, false, 0));
  x(StateLayout::stretch(1, false, 0)) += 1e-3;
  sim.setState(x);
  // The mass on the stretch: the load and the link's far-end half (docs/MODEL.md section 12).
  const double k = 2e5, c = 1e3, m = 50.0 + 2.5;
  const double rate = c / (2.0 * m), omega = std::sqrt(k / m - rate * rate);
  // The exact response from (1 mm, at rest): y = A e^(-rate t) (cos(omega t) + rate / omega sin(omega t)).
  double worst = 0.0;
  for (int i = 1; i <= 200; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.time();
    const double exact = 1e-3 * std::exp(-rate * t) * (std::cos(omega * t) + rate / omega * std::sin(omega * t));
    worst = std::max(worst, std::abs(sim.state()(StateLayout::stretch(1, false, 0)) - rest - exact));
  }
  std::cout << "damped stretch: largest difference from the closed form " << worst << " m of 1e-3 m\n";
  // Measured: 3.1e-10 m (RK4 at omega dt = 0.063; with a 5 % error in c the difference would be 1e-5 m).
  // Bound 2e-9 m (6x).
  EXPECT_LT(worst, 2e-9);
}

namespace {

/// A weightless line streaming in a current along its own axis from a held base, its tip free (a 1 g
/// load, so that the last link stretches too). The drag along it, f = 1/2 rho C_t pi d U^2 per metre, sums
/// up from the free end: T(p) = f (L - p) at unstretched arc p.
std::string streamedLine(int n, const std::string& integrator, double dt) {
  return "cable: {links: " + std::to_string(n) +
         ", length: 10.0, diameter: 0.02, mass_per_length: 0.5, axial_stiffness: 1.0e4, axial_damping: 500.0, "
         "stiffness: {model: bending}}\nload: {mass: 0.001, mode: free}\ngravity: 0.0\n"
         "fluid: {density: 1025.0, drag_normal: 1.2, drag_tangential: 0.5, added_mass: 1.0, current: [1.0, 0.0, 0.0]}\n"
         "initial: {mode: equilibrium, elevation: 1.5707963267948966, azimuth: 0.0, torsion: 0.0}\n"
         "simulation: {integrator: " + integrator + ", dt: " + formatDt(dt) + "}\n";
}

constexpr double kStreamedDrag = 0.5 * 1025.0 * 0.5 * M_PI * 0.02;  // f at U = 1 m/s [N/m]

/// The streamed line's tip [m], x along the current, from the base.
Eigen::Vector3d streamedTip(CableSimulator& sim, int n) {
  SimulationSnapshot s;
  sim.snapshot(s);
  return s.chain.ends.col(n) - s.chain.ends.col(0);
}

}  // namespace

// The skin friction along the links split with their mass (docs/MODEL.md section 12): the near half's on
// each link's body, the far half's on its far-end point beyond the stretch, at that point's own velocity;
// against the streamed line's closed forms.
// - The dynamics' drag acts on each link's unstretched length l: the line at rest stretches by
//   f L^2 / (2 EA) (T(p) integrated), and each stretch carries the tension at its link's middle, which
//   the midpoint rule sums exactly: the tip is there for any n, up to what the run leaves of its start.
// - The statics' drag acts on the stretched levers l + s: dT/dp = -f (1 + T / EA), T = EA (exp(f (L - p) /
//   EA) - 1), and the tip streams out to (EA / f) (exp(f L / EA) - 1), which the lumping meets to second
//   order in n.
// With the whole skin friction on each link's body (until session 29), each stretch carried the tension
// at its far end: the elongation short by f L l / (2 EA), 1 / n of it (first order).
TEST(AxialElasticity, AStreamedLineStretchesAsItsDragSumsUp) {
  const double f = kStreamedDrag, L = 10.0, ea = 1.0e4;
  const double dynamic_tip = L + f * L * L / (2.0 * ea);
  const double static_tip = ea / f * std::expm1(f * L / ea);
  std::vector<double> static_errors;
  for (int n : {10, 20, 40}) {
    CableSimulator sim(loadConfigString(streamedLine(n, "rk4", 1e-4)), SimulatorUse::kStaticsOnly);
    const Eigen::Vector3d tip = streamedTip(sim, n);
    static_errors.push_back((tip.x() - static_tip) / (static_tip - L));
    std::cout << "streamed line, statics, n = " << n << ": tip " << tip.transpose() << " m, closed form "
              << static_tip << " m; error " << static_errors.back() << " of the elongation\n";
    EXPECT_LT(tip.tail<2>().norm(), 1e-9);  // straight along the current
  }
  std::cout << "order in n: " << order(static_errors[0], static_errors[1]) << ", "
            << order(static_errors[1], static_errors[2]) << "\n";
  // Dynamics from that start: RK4 at 0.1 ms (n = 20 allows 0.17 ms) and the implicit step at 10 ms, 3 s (the line's
  // first axial mode, 0.28 s, damped at 0.55 of critical by c_a).
  for (const auto& [integrator, dt] : {std::pair<std::string, double>{"rk4", 1e-4}, {"implicit", 1e-2}}) {
    for (int n : {10, 20}) {
      CableSimulator sim(loadConfigString(streamedLine(n, integrator, dt)));
      for (int i = 0; i < static_cast<int>(std::lround(3.0 / dt)); ++i) ASSERT_TRUE(sim.step().ok);
      const Eigen::Vector3d tip = streamedTip(sim, n);
      const double error = (tip.x() - dynamic_tip) / (dynamic_tip - L);
      std::cout << "streamed line, " << integrator << " at " << dt << " s, n = " << n << ": tip x " << tip.x()
                << " m, closed form " << dynamic_tip << " m; error " << error << " of the elongation\n";
      // Measured: 1.2e-10 of the elongation at n = 10 and 20, RK4 and implicit alike: what 3 s leave of
      // the start (the statics' equilibrium, whose drag acts on l + s). Bound 5e-10 (4x). Before
      // (session 28's build): -0.100 and -0.050 implicit, -0.149 and -0.106 RK4 (not yet settled at 3 s).
      EXPECT_LT(std::abs(error), 5e-10);
    }
  }
  // Measured: 2.71e-5 / 6.78e-6 / 1.70e-6 of the elongation at n = 10 / 20 / 40, order 2.00 and 2.00 (before:
  // -0.101 / -0.051 / -0.025, order 1.00). Bounds: 1.5e-4 at n = 10 (5.5x) and the order within [1.8, 2.2].
  EXPECT_LT(std::abs(static_errors[0]), 1.5e-4);
  EXPECT_NEAR(order(static_errors[1], static_errors[2]), 2.0, 0.2);
}

namespace {

/// Irvine's elastic catenary ("Cable Structures", 1981, eq. 2.20-2.21), from the lower end A along the
/// unstretched arc s: with H the horizontal tension and V_A the vertical one at A (V = V_A + w s),
/// x(s) = H s / EA + H / w (asinh(V / H) - asinh(V_A / H)),
/// z(s) = w s^2 / (2 EA) + V_A s / EA + H / w (sqrt(1 + (V / H)^2) - sqrt(1 + (V_A / H)^2)).
/// Solves x(L) = span, z(L) = rise for (H, V_A) by Newton's method (central differences) and returns the
/// end tensions; ea = infinity gives the inextensible catenary.
void irvineTensions(double span, double rise, double length, double w, double ea, double& lower, double& upper) {
  auto ends = [&](double h, double va) {
    const double vb = va + w * length, compliance = std::isinf(ea) ? 0.0 : 1.0 / ea;
    const double x = h * length * compliance + h / w * (std::asinh(vb / h) - std::asinh(va / h));
    const double z = w * length * length * compliance / 2.0 + va * length * compliance +
                     h / w * (std::sqrt(1.0 + vb * vb / (h * h)) - std::sqrt(1.0 + va * va / (h * h)));
    return Eigen::Vector2d(x - span, z - rise);
  };
  Eigen::Vector2d p(w * length, -0.2 * w * length);  // (H, V_A) [N]: a start on the sagging side
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d f = ends(p(0), p(1));
    if (f.norm() < 1e-12 * length) break;
    Eigen::Matrix2d jacobian;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d d = Eigen::Vector2d::Zero();
      d(j) = 1e-6 * std::abs(p(0));
      jacobian.col(j) = (ends(p(0) + d(0), p(1) + d(1)) - ends(p(0) - d(0), p(1) - d(1))) / (2.0 * d(j));
    }
    Eigen::Vector2d step = jacobian.fullPivLu().solve(f);
    while (p(0) - step(0) <= 0.0) step *= 0.5;  // keep H > 0
    p -= step;
  }
  lower = std::hypot(p(0), p(1));
  upper = std::hypot(p(0), p(1) + w * length);
}

}  // namespace

using cable_reference::GroundedCatenary;

namespace {

/// The statics of the grounded line below with the given link lengths [m] (their sum is 100 m) and the
/// fairlead `span` out: the errors of the fairlead's tension and of the anchor's horizontal pull against
/// the closed form, and the suspended length.
struct GroundedErrors {
  double fairlead = 0.0, anchor = 0.0, suspended = 0.0, closed_suspended = 0.0;
};

/// The grounded line below with link lengths `links` [m] at a horizontal span `span` [m].
CableParams groundedLine(const std::vector<double>& links, double span) {
  return loadConfigString(cable_reference::grounded_line::projectConfig(links, span));
}

GroundedErrors groundedStatics(const std::vector<double>& links, double span) {
  namespace line = cable_reference::grounded_line;
  const double length = line::kLength, w = line::weight();
  const GroundedCatenary exact = line::closedForm(span);
  CableSimulator sim(groundedLine(links, span), SimulatorUse::kStaticsOnly);
  SimulationSnapshot s;
  sim.snapshot(s);
  GroundedErrors out;
  out.fairlead = s.chain.base_force.norm() / std::hypot(exact.horizontal, exact.vertical) - 1.0;
  // The anchor holds the line's horizontal pull H and the share of the last link's weight that the bed
  // under a continuous line would carry: H is its horizontal part.
  out.anchor = s.chain.load_force.head<2>().norm() / exact.horizontal - 1.0;
  out.suspended = length - s.chain.seabed.grounded_length;
  out.closed_suspended = exact.vertical / w;
  return out;
}

}  // namespace

// A 100 m chain-like line (8 kg/m, 0.05 m: w = 58.7 N/m submerged; EA 2e5 N, strain up to 0.9 %) from an
// anchor on the bed to a fairlead 20 m above it and 90 m out, 71 m of it on a frictionless, stiff bed
// (1e6 N/m^2: it rests 8e-5 m deep). The tip carries a 1 g point so that its last link stretches too (a
// massless anchored tip locks it: MODEL.md section 12). Against the closed form above: the fairlead's
// tension and the anchor's horizontal pull H (the anchor also holds the share of the last link's weight
// that the bed under a continuous line would carry).
// Equal links, measured at n = 25, 50, 100, 200: fairlead -0.46 %, +0.071 %, +0.0032 %, +0.0064 %; anchor
// -0.90 %, +0.124 %, +0.0019 %, +0.0032 %. With half of each link's weight beyond its stretch (docs/MODEL.md
// section 12) what is left is the touchdown's error, which follows where the touchdown falls within a link
// (grounded 72.0, 71.5, 71.0, 71.375 m against 71.31 m): a rigid link cannot follow the catenary off the
// bed, the line beyond sits as if the touchdown were up to half a link off, at heights off by up to the
// curvature there (w / H = 0.093 1/m) times l^2 / 8, and H moves 0.018 % per mm of the fairlead's height.
// (With every link's weight riding at its base end, until session 28, a first-order part came on top: the
// line short by w l h / (2 EA), 5.9 mm at n = 50, +0.16 % and +0.30 % there.) MoorDyn 2.7.1's lumped
// masses on the same line (bench/moordyn/moordyn_grounded.cpp, its statics converged to 1e-8 of a node's
// weight) have the same touchdown error: +0.071 % and +0.12 % at this span and n = 50, -0.46 % and -0.91 %
// at n = 25. The 0.1 % at n = 50 is met at the fairlead, not at the anchor (0.124 %), by either.
// With the 50 links placed as a mooring analyst places them (24 of 1 m down the catenary, 16 of 0.5 m across
// the touchdown, 10 of 6.8 m on the bed), over five spans (89 to 91 m, the touchdown moving 4 m within the
// fine links): within 2.9e-4 (fairlead) and 5.4e-4 (anchor). Bounds: 3x the measured errors at n = 100 and
// 200 and about 4x on the graded line, and a fall of at least 3x from n = 50 to 200 (measured 11x and 39x).
TEST(AxialElasticity, TheStaticsIsTheElasticCatenaryWithAGroundedPart) {
  std::vector<double> top, bottom;
  for (int n : {25, 50, 100, 200}) {
    const GroundedErrors e = groundedStatics(std::vector<double>(n, 100.0 / n), 90.0);
    top.push_back(e.fairlead);
    bottom.push_back(e.anchor);
    std::cout << n << " equal links: fairlead " << e.fairlead << ", anchor " << e.anchor << ", suspended " << e.suspended
              << " m (V / w " << e.closed_suspended << ")\n";
  }
  EXPECT_LT(std::abs(top[2]), 1e-4);
  EXPECT_LT(std::abs(top[3]), 2e-4);
  EXPECT_LT(std::abs(bottom[2]), 6e-5);
  EXPECT_LT(std::abs(bottom[3]), 1e-4);
  EXPECT_GT(std::abs(top[1] / top[3]), 3.0);
  EXPECT_GT(std::abs(bottom[1] / bottom[3]), 3.0);
  std::vector<double> graded(24, 1.0);
  graded.insert(graded.end(), 16, 0.5);
  graded.insert(graded.end(), 10, 6.8);
  double worst_top = 0.0, worst_bottom = 0.0;
  for (double span : {89.0, 89.5, 90.0, 90.5, 91.0}) {
    const GroundedErrors e = groundedStatics(graded, span);
    std::cout << "graded 50 links, span " << span << " m: fairlead " << e.fairlead << ", anchor " << e.anchor
              << ", suspended " << e.suspended << " m (V / w " << e.closed_suspended << ")\n";
    worst_top = std::max(worst_top, std::abs(e.fairlead));
    worst_bottom = std::max(worst_bottom, std::abs(e.anchor));
  }
  EXPECT_LT(worst_top, 1.1e-3);
  EXPECT_LT(worst_bottom, 2.3e-3);
}

// The statics of the grounded line above graded 20 x 1.25 m, 20 x 0.5 m, 10 x 6.5 m at a 90.5 m span,
// started as the general start does (the line hanging through the bed, the bed's contact ramped up), ends
// in a kink: link 29 (0.5 m, by the touchdown) carries 978 N of compression, the fairlead's tension 13 %
// above the closed form's; from there the dynamics telescoped the slack links and the line slid (RK4 at
// 0.1 ms too). A tension-only cable has no such equilibrium: the start is refused, naming it. Started from
// its elastic catenary (the default for such a line, catenary_start.h) the same line finds its tension-only
// equilibrium: fairlead within 1e-3 of the closed form (measured -1.8e-4; 5.4x).
TEST(AxialElasticity, AnElasticEquilibriumWithACompressedLinkIsRefused) {
  std::vector<double> graded(20, 1.25);
  graded.insert(graded.end(), 20, 0.5);
  graded.insert(graded.end(), 10, 6.5);
  CableSimulator sim(groundedLine(graded, 90.5), SimulatorUse::kStaticsOnly);
  StaticOptions general;
  general.catenary_start = false;
  const StaticSolution kinked = sim.resetToEquilibrium(general);
  EXPECT_FALSE(kinked.converged);
  EXPECT_NE(kinked.message.find("link 29 in compression"), std::string::npos) << kinked.message;
  const GroundedErrors from_catenary = groundedStatics(graded, 90.5);
  std::cout << "graded at 90.5 m from the catenary: fairlead " << from_catenary.fairlead << "\n";
  EXPECT_LT(std::abs(from_catenary.fairlead), 1e-3);
  // The same line at 90 m has a tension-only equilibrium, and finds it.
  EXPECT_LT(std::abs(groundedStatics(graded, 90.0).fairlead), 1e-3);
}

TEST(AxialElasticity, TheStaticsIsIrvinesElasticCatenaryBetweenTwoPoints) {
  // A 100 m line, 10 kg/m in air (w = 98.1 N/m), EA 2e6 N, from the base to an anchor 85 m across and
  // 36 m down (the chord 92.6 m: it sags, end tensions 5.9 and 9.4 kN, strain up to 0.47 %). The tip is
  // held by the exact anchor (the statics put it on the anchor to round-off); the closed form is taken
  // between the base and the tip. The tip carries a 1 g point (a load with mass, so that the last link
  // stretches too; its weight is 1e-6 of the tensions).
  std::vector<double> errors_lower, errors_upper;
  double stiff_lower = 0.0, stiff_upper = 0.0, upper_last = 0.0;
  for (int n : {25, 50, 100}) {
    CableSimulator sim(
        loadConfigString("cable: {links: " + std::to_string(n) +
                         ", length: 100.0, diameter: 0.05, mass_per_length: 10.0, axial_stiffness: 2.0e6, "
                         "stiffness: {model: bending}}\nload: {mass: 0.001, mode: anchored, "
                         "motion: {offset: [0.0, 8.0, 0.0]}}\nfluid: {density: 0.0}\n"
                         "initial: {mode: equilibrium, elevation: 1.2, azimuth: 0.0, torsion: 0.0}\n"
                         "simulation: {integrator: rk4, dt: 0.0001}\n"),
        SimulatorUse::kStaticsOnly);
    SimulationSnapshot s;
    sim.snapshot(s);
    const Eigen::Vector3d tip = s.chain.ends.col(n) - s.chain.ends.col(0);  // paper frame, z down [m]
    const double span = std::hypot(tip.x(), tip.y()), rise = tip.z(), w = 10.0 * 9.81;
    double lower = 0.0, upper = 0.0;
    irvineTensions(span, rise, 100.0, w, 2.0e6, lower, upper);
    irvineTensions(span, rise, 100.0, w, INFINITY, stiff_lower, stiff_upper);
    upper_last = upper;
    errors_lower.push_back(s.chain.load_force.norm() / lower - 1.0);
    errors_upper.push_back(s.chain.base_force.norm() / upper - 1.0);
    std::cout << "n = " << n << ": span " << span << " m, rise " << rise << " m; tensions " << s.chain.base_force.norm()
              << " / " << s.chain.load_force.norm() << " N, Irvine " << upper << " / " << lower
              << " N (inextensible " << stiff_upper << " / " << stiff_lower << "); errors " << errors_upper.back()
              << " / " << errors_lower.back() << "\n";
  }
  std::cout << "order in n (top, bottom): " << order(errors_upper[1], errors_upper[2]) << ", "
            << order(errors_lower[1], errors_lower[2]) << "\n";
  // Measured (top / bottom): -3.79e-4 / -4.81e-4 at n = 25, -9.47e-5 / -1.19e-4 at n = 50, -2.37e-5 /
  // -2.91e-5 at n = 100: second order (2.00 and 2.03), with half of each link's weight beyond its stretch
  // (docs/MODEL.md section 12); the elastic effect itself is 1.3 % (the inextensible catenary's tensions
  // between the same points). With every link's mass at its base end (until session 28) there was no clean
  // order: -7.5e-6 / -6.3e-5 at n = 50, the top's error changing sign between 50 and 100 (a first-order
  // part against the second-order one of rigid links). Bounds at n = 50: 6e-4 (5x the larger measured
  // error; the issue asks 0.1 %), and both orders within [1.8, 2.2].
  EXPECT_LT(std::abs(errors_upper[1]), 6e-4);
  EXPECT_LT(std::abs(errors_lower[1]), 6e-4);
  EXPECT_NEAR(order(errors_upper[1], errors_upper[2]), 2.0, 0.2);
  EXPECT_NEAR(order(errors_lower[1], errors_lower[2]), 2.0, 0.2);
  // The elasticity is resolved: between the same points (n = 100's) the inextensible catenary's top
  // tension differs from the elastic one by far more than the error.
  EXPECT_GT(std::abs(stiff_upper / upper_last - 1.0), 10.0 * std::abs(errors_upper[2]));
}

// A slack link's chord may shorten to two thirds of its length, no further (forces/axial_spring.h,
// kSlackStop): beyond, its stretch meets a stop as stiff as its spring. One 1 m link of 1 kg in zero gravity
// and air, a 1 kg free load at its tip; what moves along the link is the load and the link's far-end point
// (half the link's mass, docs/MODEL.md section 12): M = 1.5 kg. Moving in at 1 m/s from 0.1 m short of the
// stop at s = -l/3, it coasts to it (0.1 s), rides the stop's spring k = EA / l = 1e4 N/m for half a period,
// pi sqrt(M / k) = 38.5 ms, down to -l/3 - v sqrt(M / k), and leaves it at 1 m/s; the stop pushes with at
// most k v sqrt(M / k) = 122 N. RK4 at 0.1 ms (h omega = 0.008). Measured: the deepest stretch, the rebound
// speed and the peak push within 2e-6 relative, the time in the stop within 1e-4 s (the step); bounds 1e-5
// and 3e-4 s. Before the stop (session 23) a slack link telescoped without limit: config/rov_dive.yaml with
// EA had its last link at -23 times its length.
TEST(AxialElasticity, ASlackLinkShortensToTwoThirdsOfItsLengthAndNoFurther) {
  CableSimulator sim(loadConfigString(
      "cable: {links: 1, length: 1.0, diameter: 0.01, mass_per_length: 1.0, axial_stiffness: 1.0e4, "
      "stiffness: {model: bending}}\nload: {mass: 1.0, mode: free}\nfluid: {density: 0.0}\ngravity: 0.0\n"
      "initial: {elevation: 0.0, azimuth: 0.0, torsion: 0.0}\nsimulation: {integrator: rk4, dt: 0.0001}\n"));
  const double stop = -1.0 / 3.0, moving = 1.5;  // [m], [kg]
  Eigen::VectorXd x = sim.state();
  x(StateLayout::stretch(1, false, 0)) = stop + 0.1;
  x(StateLayout::stretchRate(1, false, 0)) = -1.0;
  sim.setState(x);
  SimulationSnapshot snap;
  double deepest = 0.0, push = 0.0, entered = -1.0, left = -1.0, rebound = 0.0;
  for (int i = 0; i < 3000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    sim.snapshot(snap);
    const double s = snap.chain.stretch(0);
    deepest = std::min(deepest, s);
    push = std::min(push, snap.chain.far_tension(0));
    if (entered < 0.0 && s < stop) entered = sim.time();
    if (entered >= 0.0 && left < 0.0 && s > stop) {
      left = sim.time();
      rebound = sim.state()(StateLayout::stretchRate(1, false, 0));
    }
  }
  const double omega = std::sqrt(1.0e4 / moving);
  std::cout << std::setprecision(10) << "deepest " << deepest << " m, push " << push << " N, in the stop " << entered << " to " << left
            << " s, rebound " << rebound << " m/s\n";
  EXPECT_NEAR(deepest / (stop - 1.0 / omega) - 1.0, 0.0, 1e-5);
  EXPECT_NEAR(push / (-1.0e4 * (1.0 / omega)) - 1.0, 0.0, 1e-5);
  EXPECT_NEAR(rebound - 1.0, 0.0, 1e-5);
  EXPECT_NEAR(left - entered, M_PI / omega, 3e-4);
  EXPECT_NEAR(entered, 0.1, 3e-4);
}

TEST(AxialElasticity, BadInputsAreRefusedWithTheKey) {
  const std::string cable = "cable: {links: 4, length: 10.0, diameter: 0.02, mass_per_length: 1.0, ";
  const std::string rest = "stiffness: {model: bending}}\nload: {mass: 1.0}\nsimulation: {integrator: rk4, dt: 0.0001}\n";
  auto refused = [](const std::string& yaml, std::string& message) {
    try {
      loadConfigString(yaml);
    } catch (const ConfigError& e) {
      message = e.what();
      return e.key();
    }
    return std::string("(accepted)");
  };
  std::string message;
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, " + rest, message), "(accepted)");
  EXPECT_EQ(refused(cable + "axial_stiffness: -1.0, " + rest, message), "cable.axial_stiffness");
  EXPECT_EQ(refused(cable + "axial_stiffness: .nan, " + rest, message), "cable.axial_stiffness");
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, axial_damping: -1.0, " + rest, message), "cable.axial_damping");
  EXPECT_EQ(refused(cable + "axial_damping: 10.0, " + rest, message), "cable.axial_damping");
  // Its own weight in water, 10 m of 1 kg/m less 0.322 kg/m of buoyancy: 66.5 N; an EA below twice it
  // would stretch the cable beyond 50 % under it.
  EXPECT_EQ(refused(cable + "axial_stiffness: 100.0, " + rest, message), "cable.axial_stiffness");
  EXPECT_NE(message.find(">= 133.0"), std::string::npos) << message;
  EXPECT_EQ(refused(cable + "axial_stiffness: 140.0, " + rest, message), "(accepted)");
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, stiffness: {model: bending}}\nload: {mass: 1.0}\n"
                            "simulation: {integrator: implicit, dt: 0.01}\n", message),
            "(accepted)");
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, stiffness: {model: bending}}\nload: {mass: 1.0}\n"
                            "simulation: {integrator: semi_implicit, dt: 0.01}\n", message),
            "simulation.integrator");
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5}\nload: {mass: 1.0}\n"
                            "simulation: {formulation: paper, integrator: rk4, dt: 0.0001}\n", message),
            "simulation.formulation");
  // A winch pays out unstretched length (test_winch_stretch).
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, stiffness: {model: bending}}\nload: {mass: 1.0}\n"
                            "winch: {max_length: 20.0, min_length: 5.0}\nsimulation: {integrator: rk4, dt: 0.0001}\n", message),
            "(accepted)");
  // A section that would stay rigid while another stretches.
  EXPECT_EQ(refused(cable + "sections: [{length: 5.0, axial_stiffness: 1.0e5}, {}], " + rest, message),
            "cable.sections[1].axial_stiffness");
  EXPECT_EQ(refused(cable + "axial_stiffness: 1.0e5, sections: [{length: 5.0, axial_stiffness: 2.0e5}, {}], " + rest,
                    message),
            "(accepted)");
}
