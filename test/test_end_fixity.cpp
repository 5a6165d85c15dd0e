// The clamp at the base of a stiff cable (bending model) against closed forms nobody here wrote: a
// cantilever's tip deflection under a uniform load, w L^4 / (8 EI), and the first torsional frequency of
// a fixed-free rod, (pi / 2L) sqrt(GJ / (rho I_p)). Both converge at second order in 1/n because joint 1's
// springs are EI and GJ over the half link between the clamp and link 1's centre (cable_params.cpp); with
// a whole link there the errors were about 2/n and 1/(2n) (issue 14, item 3).
#include <cmath>
#include <iomanip>
#include <iostream>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"

using namespace cable_dynamics;

namespace {

constexpr double kLength = 10.0;    // [m]
constexpr double kDiameter = 0.025;  // [m]
constexpr double kMassPerLength = 0.6;  // [kg/m]

CableParams stiffCable(int n, const std::vector<std::string>& extra) {
  std::vector<std::string> o = {"cable.links=" + std::to_string(n)};
  o.insert(o.end(), extra.begin(), extra.end());
  return loadConfigString("cable: {links: 1, length: 10.0, diameter: 0.025, mass_per_length: 0.6}\n", o);
}

/// log2 of successive error ratios: the observed order of convergence when n doubles.
double order(double coarse, double fine) { return std::log2(std::abs(coarse / fine)); }

}  // namespace

TEST(EndFixity, CantileverTipDeflectionConvergesAtSecondOrder) {
  // A cable clamped at the base pointing down, in a uniform 0.25 m/s current with no gravity: the
  // normal Morison drag w = 1/2 rho C_n d U^2 = 0.96 N/m is a uniform load across it (the tip turns by
  // 0.003 rad, so the cos^2 of the deflection changes w by 1e-5 and the geometry is linear to the same
  // order). EI = 48 kN m^2. The static shape comes from the semi-implicit integrator, whose fixed points
  // are the dynamics' own (SemiImplicitReachesTheSameSteadyState), stepped 30 s at 10 ms: the drag
  // damps the motion out (the tip moves by less than 1e-12 m in the last second).
  const double ei = 48000.0, current = 0.25;
  const double w = 0.5 * 1025.0 * 1.2 * kDiameter * current * current;
  const double exact = w * std::pow(kLength, 4) / (8.0 * ei);
  std::vector<double> errors;
  for (int n : {10, 20, 40}) {
    CableSimulator sim(stiffCable(n, {"cable.stiffness={model: bending, bending_rigidity: 48000}",
                                      "fluid={density: 1025, drag_normal: 1.2, drag_tangential: 0.0, current: [0.25, 0, 0]}",
                                      "gravity=0", "simulation={integrator: semi_implicit, dt: 0.01}"}));
    SimulationSnapshot s;
    double before = 0.0;
    for (int i = 0; i < 3000; ++i) {
      ASSERT_TRUE(sim.step().ok);
      if (i == 2899) {
        sim.snapshot(s);
        before = s.chain.ends(0, n);
      }
    }
    sim.snapshot(s);
    const double tip = s.chain.ends(0, n);  // paper x = world x: along the current [m]
    EXPECT_LT(std::abs(tip - before), 1e-9) << "not settled at n = " << n;
    errors.push_back(tip / exact - 1.0);
    std::cout << "cantilever n = " << std::setw(2) << n << ": tip " << tip << " m, w L^4/(8 EI) = " << exact
              << " m, error " << 100 * errors.back() << " %\n";
  }
  std::cout << "observed order: " << order(errors[0], errors[1]) << ", " << order(errors[1], errors[2]) << "\n";
  EXPECT_GT(order(errors[0], errors[1]), 1.8);
  EXPECT_GT(order(errors[1], errors[2]), 1.8);
  EXPECT_LT(std::abs(errors[2]), 0.005);  // the bound at n = 40; measured 0.06 %
}

TEST(EndFixity, FixedFreeTorsionFrequencyConvergesAtSecondOrder) {
  // A cable hanging straight down in air, clamped at the base, twisting: sigma_k is each link's twist
  // and omega_z = -sigma' there, so the linearized torsion dynamics are sigma'' = -K sigma with
  // K = d(omega_z')/d(sigma), taken from the simulator's own derivative by central differences. Its
  // smallest eigenvalue is omega_1^2; the continuous rod's is ((pi / 2L) sqrt(GJ / (rho I_p)))^2 with
  // rho I_p = m' r^2 / 2 (the links are solid cylinders of the outer diameter).
  const double gj = 100.0;
  const double radius = 0.5 * kDiameter;
  const double exact = M_PI / (2.0 * kLength) * std::sqrt(gj / (kMassPerLength * radius * radius / 2.0));
  std::vector<double> errors;
  for (int n : {10, 20, 40}) {
    ChainDynamics chain(stiffCable(n, {"cable.stiffness={model: bending, torsional_rigidity: 100}", "fluid.density=0"}));
    Eigen::VectorXd x = Eigen::VectorXd::Zero(chain.stateSize()), rate(chain.stateSize()), rate_minus(chain.stateSize());
    for (int k = 0; k < n; ++k) x(StateLayout::axis(k) + 2) = 1.0;  // straight down
    Eigen::MatrixXd stiffness(n, n);
    const double eps = 1e-6;  // [rad]: the torques are linear in the twist here, so the difference is exact
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd xp = x, xm = x;
      xp(StateLayout::twist(j)) += eps;
      xm(StateLayout::twist(j)) -= eps;
      ASSERT_TRUE(chain.derivative(xp, EndInputs(), rate));
      ASSERT_TRUE(chain.derivative(xm, EndInputs(), rate_minus));
      for (int k = 0; k < n; ++k) {
        stiffness(k, j) = (rate(StateLayout::omega(k) + 2) - rate_minus(StateLayout::omega(k) + 2)) / (2.0 * eps);
      }
    }
    Eigen::EigenSolver<Eigen::MatrixXd> eig(stiffness);
    double smallest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      EXPECT_LT(std::abs(eig.eigenvalues()(i).imag()), 1e-6 * std::abs(eig.eigenvalues()(i).real()));
      smallest = std::min(smallest, eig.eigenvalues()(i).real());
    }
    ASSERT_GT(smallest, 0.0);
    const double omega = std::sqrt(smallest);
    errors.push_back(omega / exact - 1.0);
    std::cout << "torsion n = " << std::setw(2) << n << ": omega_1 " << omega << " rad/s, (pi/2L) sqrt(GJ/(rho I_p)) = "
              << exact << " rad/s, error " << 100 * errors.back() << " %\n";
  }
  std::cout << "observed order: " << order(errors[0], errors[1]) << ", " << order(errors[1], errors[2]) << "\n";
  EXPECT_GT(order(errors[0], errors[1]), 1.8);
  EXPECT_GT(order(errors[1], errors[2]), 1.8);
  EXPECT_LT(std::abs(errors[2]), 0.005);
}

/// Every link along the paper frame's +x (elevation pi/2, absolute azimuth pi/2: the first joint's
/// relative azimuth pi/2, the others 0), as config overrides.
std::vector<std::string> horizontalStart(int n) {
  std::string azimuths = "initial.azimuth=[1.5707963267948966";
  for (int k = 1; k < n; ++k) azimuths += ", 0";
  return {"initial.elevation=1.5707963267948966", azimuths + "]"};
}

TEST(EndFixity, HorizontalClampCarriesACantileverUnderGravity) {
  // base.direction = [1, 0, 0]: the clamp holds link 1 horizontal (an I-tube), the cable in air sags
  // under its weight w = m' g. Tip deflection against w L^4 / (8 EI), EI = 736 kN m^2 (1 cm; the tip
  // turns by 1.3e-3 rad, so the geometry is linear to about 1e-6). Static shape from the semi-implicit
  // integrator, whose numerical damping settles the motion in air (first mode 39 rad/s, dt = 10 ms).
  const double ei = 7.36e5, w = kMassPerLength * 9.81;
  const double exact = w * std::pow(kLength, 4) / (8.0 * ei);
  std::vector<double> errors;
  for (int n : {10, 20, 40}) {
    std::vector<std::string> o = {"cable.stiffness={model: bending, bending_rigidity: 736000}", "fluid.density=0",
                                  "base.direction=[1, 0, 0]", "simulation={integrator: semi_implicit, dt: 0.01}"};
    for (const std::string& start : horizontalStart(n)) o.push_back(start);
    CableSimulator sim(stiffCable(n, o));
    for (int i = 0; i < 2000; ++i) ASSERT_TRUE(sim.step().ok);
    SimulationSnapshot s;
    sim.snapshot(s);
    EXPECT_NEAR(s.chain.ends(0, n), kLength, 1e-3);  // still along +x
    const double sag = s.chain.ends(2, n);            // paper z: down [m]
    errors.push_back(sag / exact - 1.0);
    std::cout << "horizontal clamp n = " << std::setw(2) << n << ": tip sag " << sag << " m, w L^4/(8 EI) = " << exact
              << " m, error " << 100 * errors.back() << " %, top tension " << s.chain.tension(0) << " N\n";
    // The clamp carries the weight: the base force is the cable's weight, straight down (paper +z).
    EXPECT_NEAR(-s.chain.base_force.z(), -w * kLength, 1e-6 * w * kLength);
  }
  EXPECT_GT(order(errors[0], errors[1]), 1.8);
  EXPECT_GT(order(errors[1], errors[2]), 1.8);
  EXPECT_LT(std::abs(errors[2]), 0.005);
}

/// Mean period of the tip's paper-y coordinate (a link at azimuth 0 leans along y) [s], from its upward zero crossings over `duration`.
double tipSwingPeriod(CableSimulator& sim, double duration) {
  std::vector<double> crossings;
  SimulationSnapshot s;
  sim.snapshot(s);
  double previous = s.chain.ends(1, sim.links()), previous_time = sim.time();
  const long steps = std::lround(duration / sim.dt());
  for (long i = 0; i < steps; ++i) {
    EXPECT_TRUE(sim.step().ok);
    sim.snapshot(s);
    const double x = s.chain.ends(1, sim.links());
    if (previous < 0.0 && x >= 0.0) crossings.push_back(previous_time + (sim.time() - previous_time) * (-previous) / (x - previous));
    previous = x;
    previous_time = sim.time();
  }
  EXPECT_GE(crossings.size(), 2u);
  return crossings.size() < 2 ? 0.0 : (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(EndFixity, PinnedBaseLetsAStiffCableSwingAsARod) {
  // base.fixity: pinned leaves link 1 free to turn at the base: a stiff cable (EI = 1e5 N m^2, its
  // first bending mode ~10 times faster than the swing) started straight at 0.05 rad from the
  // vertical swings as a uniform rod pinned at its end, period 2 pi sqrt(2 L / (3 g)) (small amplitude:
  // the theta^2/16 correction is 1.6e-4; the rod's flexibility and the links' thickness inertia add
  // about 1e-3). Clamped, the same start bends it instead: it vibrates in its cantilever modes (the
  // first at 1.875^2 sqrt(EI / (m' L^4)), a period of 0.44 s; a straight tilted start excites the
  // higher ones too, so its tip crosses the vertical more often still), never swinging as a rod.
  const int n = 20;
  const double rod = 2.0 * M_PI * std::sqrt(2.0 * kLength / (3.0 * 9.81));
  const double cantilever = 2.0 * M_PI / (1.875104 * 1.875104 * std::sqrt(1.0e5 / (kMassPerLength * std::pow(kLength, 4))));
  const std::vector<std::string> common = {"cable.stiffness={model: bending, bending_rigidity: 1.0e5}", "fluid.density=0",
                                           "initial.elevation=0.05", "simulation.dt=0.0001"};
  std::vector<std::string> pinned = common, clamped = common;
  pinned.push_back("base.fixity=pinned");
  CableSimulator swing(stiffCable(n, pinned)), vibrate(stiffCable(n, clamped));
  const double swing_period = tipSwingPeriod(swing, 12.0), vibration_period = tipSwingPeriod(vibrate, 2.0);
  std::cout << "pinned: period " << swing_period << " s, rod 2 pi sqrt(2L/3g) = " << rod << " s (error "
            << 100 * (swing_period / rod - 1) << " %); clamped: period " << vibration_period
            << " s (cantilever mode 1 without gravity: " << cantilever << " s)\n";
  EXPECT_NEAR(swing_period / rod, 1.0, 0.005);
  EXPECT_GT(vibration_period, 0.0);
  EXPECT_LT(vibration_period, cantilever * 1.05);  // no slower than the first bending mode: no swing

}
