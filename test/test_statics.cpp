// The static solver (statics/static_solver.h) against closed forms nobody here wrote: the inextensible
// catenary between two points, the force balance of a cable in a current, a cantilever's w L^4 / (8 EI);
// and against the dynamics themselves: a solved equilibrium has zero angular accelerations.
#include <cmath>
#include <iomanip>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/dynamics/joint_geometry.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/statics/static_solver.h"

using namespace cable_dynamics;

namespace {

constexpr double kGravity = 9.81;       // [m/s^2]
constexpr double kMassPerLength = 0.6;  // [kg/m]

CableParams cable(double length, int n, const std::vector<std::string>& extra) {
  std::vector<std::string> o = {"cable.links=" + std::to_string(n), "cable.length=" + std::to_string(length)};
  o.insert(o.end(), extra.begin(), extra.end());
  return loadConfigString("cable: {links: 1, length: 10.0, diameter: 0.025, mass_per_length: 0.6}\n", o);
}

/// Solves with the dynamics' own model and current, prints the iterations, and checks convergence.
StaticSolution solve(ChainDynamics& chain, const StaticProblem& problem, const char* name, int most_iterations = 30) {
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), problem);
  std::cout << name << ": converged " << s.converged << " in " << s.iterations << " Newton iterations, residual "
            << s.residual << (s.message.empty() ? "" : ", ") << s.message << "\n";
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_LT(s.residual, StaticOptions().tolerance);
  EXPECT_LE(s.iterations, most_iterations);
  return s;
}

/// The state of a solved shape at rest, the accumulators zero.
Eigen::VectorXd restState(const StaticSolution& s) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(StateLayout::size(static_cast<int>(s.twists.size())));
  setRestState(s, x);
  return x;
}

/// Bound on restAcceleration() at a solved shape [g / l]: the statics stop at a relative residual of
/// 1e-9; measured at most 9.9e-10 (the stiff cable in a current), 10x above. The catenary between two
/// points has its own (kCatenaryRestTolerance).
constexpr double kRestTolerance = 1e-8;
/// The catenary's tip held by the exact anchor: measured 2.2e-9, 1.4e-13, 4.4e-9 at n = 25, 50, 100 (the
/// limp sweep's round-off; with the 1e7 N/m coupling spring it was 3.1e-9, 1.7e-8, 9.9e-8); 5x above the largest.
constexpr double kCatenaryRestTolerance = 2e-8;

/// Largest angular acceleration of the dynamics at the solved shape, relative to g / l_min.
double restAcceleration(ChainDynamics& chain, const StaticSolution& s, const StaticProblem& problem) {
  EndInputs ends;
  ends.base_position = problem.base_position;
  ends.load_coupled = problem.tip_coupled;
  // An exact anchor's hold is judged at the tip where the statics put it (within 1e-12 of the length of
  // the anchor): its drift correction turns a miss of 1e-11 m into 1e-5 m/s^2 at a 1 ms step, which says
  // nothing about the force balance this checks (the miss itself is checked by the callers).
  ends.target_position = chain.model().heldTip() ? s.tip_position : problem.target_position;
  const Eigen::VectorXd x = restState(s);
  Eigen::VectorXd rate(x.size());
  EXPECT_TRUE(chain.derivative(x, ends, rate));
  double worst = 0.0;
  for (int k = 0; k < chain.links(); ++k) worst = std::max(worst, rate.segment<3>(StateLayout::omega(k)).norm());
  return worst / (kGravity / chain.properties().length.minCoeff());
}

/// The inextensible catenary through (0, 0) and (span, -drop) (x horizontal, height up) of length L:
/// sqrt(L^2 - drop^2) = 2 a sinh(span / 2a) for a, then the vertex x0 = span/2 - a atanh(-drop / L).
/// Gives the end tensions for weight w per length and the lowest point's depth below the first end.
struct Catenary {
  double a, x0, tension_first, tension_second, lowest_depth;
};
Catenary catenary(double length, double span, double drop, double w) {
  const double target = std::sqrt(length * length - drop * drop);
  double lo = 1e-6 * span, hi = 1e6 * span;  // 2 a sinh(span / 2a) falls from infinity to span as a grows
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (2.0 * mid * std::sinh(span / (2.0 * mid)) > target ? lo : hi) = mid;
  }
  Catenary c;
  c.a = std::sqrt(lo * hi);
  c.x0 = 0.5 * span - c.a * std::atanh(-drop / length);
  c.tension_first = w * c.a * std::cosh(-c.x0 / c.a);
  c.tension_second = w * c.a * std::cosh((span - c.x0) / c.a);
  c.lowest_depth = c.a * (std::cosh(-c.x0 / c.a) - 1.0);  // the vertex lies between the ends here
  return c;
}

}  // namespace

TEST(Statics, CatenaryBetweenTwoPoints) {
  // A limp chain in air, L = 100 m, its tip held exactly 80 m across and 20 m below the base (the exact
  // anchor: the statics put the tip on it, and its hold carries the anchor's pull). The discrete chain is the
  // polygon inscribed in the catenary with its weight lumped... at the links' centres: it converges to
  // the catenary at second order in 1/n.
  const double length = 100.0, span = 80.0, drop = 20.0, w = kMassPerLength * kGravity;
  const Catenary exact = catenary(length, span, drop, w);
  std::vector<double> worst, tension_errors;
  for (int n : {25, 50, 100}) {
    ChainDynamics chain(cable(length, n, {"fluid.density=0", "load={mass: 0, mode: anchored}"}));
    StaticProblem problem;
    problem.tip_coupled = true;
    problem.target_position = Eigen::Vector3d(span, 0.0, drop);
    const StaticSolution s = solve(chain, problem, "catenary");
    Eigen::Matrix3Xd nodes(3, n + 1);
    nodes.col(0) = problem.base_position;
    for (int k = 0; k < n; ++k) nodes.col(k + 1) = nodes.col(k) + chain.properties().length(k) * s.axes.col(k);
    const double lowest = nodes.row(2).maxCoeff();  // paper z is depth [m]
    const double first = s.joint_force.col(0).norm();  // the base's reaction = the tension there [N]
    const double second = s.hold_force.norm();  // the anchor's pull [N]
    EXPECT_LT((s.tip_position - problem.target_position).norm(), 1e-9);  // on the anchor
    const double e_first = first / exact.tension_first - 1.0, e_second = second / exact.tension_second - 1.0;
    const double e_lowest = lowest / exact.lowest_depth - 1.0;
    std::cout << std::setprecision(6) << "catenary n = " << n << ": T_base " << first << " N (exact " << exact.tension_first
              << ", error " << 100 * e_first << " %), T_tip " << second << " N (exact " << exact.tension_second << ", error "
              << 100 * e_second << " %), lowest depth " << lowest << " m (exact " << exact.lowest_depth << ", error "
              << 100 * e_lowest << " %), tension(0) along link 1 " << s.tension(0) << " N\n";
    worst.push_back(std::max({std::abs(e_first), std::abs(e_second), std::abs(e_lowest)}));
    tension_errors.push_back(std::abs(e_first));
    if (n == 50) {
      // The chain's discretization (second order in the link length): measured 0.0099 % (the lowest
      // node; the end tensions 0.0043 %); 5x above.
      EXPECT_LT(worst.back(), 5e-4);
    }
    const double rest = restAcceleration(chain, s, problem);
    std::cout << "catenary n = " << n << ": largest angular acceleration " << rest << " g/l\n";
    EXPECT_LT(rest, kCatenaryRestTolerance);
  }
  // The end tensions converge cleanly at second order; the lowest node samples the continuous lowest
  // point, so its error changes sign (measured -0.047 %, +0.0099 %, -0.0012 %) and is only bounded.
  std::cout << "catenary: base tension error ratios n 25->50 " << tension_errors[0] / tension_errors[1] << ", 50->100 "
            << tension_errors[1] / tension_errors[2] << " (4 at second order)\n";
  EXPECT_NEAR(tension_errors[0] / tension_errors[1], 4.0, 0.2);
  EXPECT_NEAR(tension_errors[1] / tension_errors[2], 4.0, 0.2);
  EXPECT_LT(worst[2], worst[0]);
}

TEST(Statics, FreeTipInACurrentBalancesTheTotalForce) {
  // The default umbilical (config/default.yaml: 50 m, 25 links, 10 kg load) with a load drag area, in
  // a 0.3 m/s current: the base's reaction equals the sum of every external force. The links' drag is
  // recomputed here from the Morison formula on straight links (uniform current, at rest: the same
  // along each link, so its integral is l times the per-metre value, no quadrature).
  ChainDynamics chain(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml", {"load.drag_area=0.3"}));
  const StaticSolution s = solve(chain, StaticProblem(), "free tip in a current");
  const CableParams params = loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml", {"load.drag_area=0.3"});
  // The config's current (world frame, z up) is along x, which the paper frame (z down) shares.
  ASSERT_EQ(params.fluid.current.y(), 0.0);
  ASSERT_EQ(params.fluid.current.z(), 0.0);
  const Eigen::Vector3d current(params.fluid.current.x(), 0.0, 0.0);  // [m/s]
  const double rho = params.fluid.density, d = params.diameter;
  // Weights less buoyancy from the config's numbers (paper z points down): the load's, and each link's
  // (mass per length - rho pi d^2 / 4) l.
  Eigen::Vector3d total = (params.load.mass - rho * params.load.volume) * params.gravity * Eigen::Vector3d::UnitZ() +
                          0.5 * rho * 0.3 * current.norm() * current;
  for (int k = 0; k < chain.links(); ++k) {
    const double l = params.totalLength() / params.links;  // equal links [m]
    // Morison, written here (not the library's morisonDragPerLength): the current's part normal to the
    // link, u_n = u - (u.t) t, drags with 1/2 rho C_n d |u_n| u_n per metre, its part along it with the
    // skin friction 1/2 rho C_t (pi d) |u.t| (u.t) t.
    const Eigen::Vector3d t = s.axes.col(k);
    const double along = current.dot(t);
    const Eigen::Vector3d normal = current - along * t;
    const Eigen::Vector3d drag = 0.5 * rho * (params.fluid.drag_normal * d * normal.norm() * normal +
                                              params.fluid.drag_tangential * M_PI * d * std::abs(along) * along * t);
    total += (params.mass_per_length - rho * M_PI * d * d / 4.0) * l * params.gravity * Eigen::Vector3d::UnitZ() + l * drag;
  }
  const double error = (s.joint_force.col(0) + total).norm() / total.norm();
  std::cout << "total force balance: base reaction " << -s.joint_force.col(0).transpose() << " N, sum of loads "
            << total.transpose() << " N, relative error " << error << "\n";
  // Round-off of a sum of 27 forces (measured 3.2e-16 relative); 10x above.
  EXPECT_LT(error, 3e-15);
  EXPECT_GT(s.tension(0), 0.0);
  EXPECT_LT(restAcceleration(chain, s, StaticProblem()), kRestTolerance);
}

TEST(Statics, HeavyLoadTopAngleMatchesAStraightCable) {
  // A 448.75 kg (submerged) clump under 50 m of the default cable in a 0.3 m/s current: the cable is
  // nearly straight at a small angle theta from the vertical, and the force balance of a straight cable
  // at theta in a current U along x (normal drag q cos^2 theta per metre normal to it, q = 1/2 rho C_n d
  // U^2, skin friction 1/2 rho C_t pi d (U sin theta)^2 along it) gives
  //   tan theta = (D_load + L (q cos^3 theta + t sin^3 theta)) / (W_load + W_cable - L (q cos^2 theta sin theta - t sin^2 theta cos theta)).
  // The cable's angle varies along it by ~0.6 degree, which changes cos^3 by ~1e-4: well inside 0.5 %.
  const std::vector<std::string> o = {"load={mass: 500, volume: 0.05, drag_area: 1.0}", "fluid.current=[0.3, 0, 0]"};
  ChainDynamics chain(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml", o));
  const CableParams params = loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml", o);
  const StaticSolution s = solve(chain, StaticProblem(), "heavy load in a current");
  const double rho = params.fluid.density, d = params.diameter, u = 0.3, length = params.totalLength();
  const double q = 0.5 * rho * params.fluid.drag_normal * d * u * u, t = 0.5 * rho * params.fluid.drag_tangential * M_PI * d * u * u;
  const double drag_load = 0.5 * rho * 1.0 * u * u, weight = chain.model().load().weight + kGravity * chain.properties().submerged_mass.sum();
  double theta = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double c = std::cos(theta), sn = std::sin(theta);
    theta = std::atan((drag_load + length * (q * c * c * c + t * sn * sn * sn)) / (weight - length * (q * c * c * sn - t * sn * sn * c)));
  }
  const double top = std::atan2(std::hypot(s.axes(0, 0), s.axes(1, 0)), s.axes(2, 0));
  const double reaction = std::atan2(std::hypot(s.joint_force(0, 0), s.joint_force(1, 0)), -s.joint_force(2, 0));
  std::cout << "heavy load: top link at " << top << " rad, base reaction at " << reaction << " rad, straight cable "
            << theta << " rad (error " << 100 * (reaction / theta - 1) << " %)\n";
  // The top link itself lies along the mean of the tension over its length (its own drag and weight
  // turn the tension by F_0 / 2 across it): a first-order (1/n) offset from the tangent at the base,
  // 1.2 % here at n = 25, which is why the angle compared is the reaction's.
  // A model error, not a numerical one: the straight cable's formula against the chain whose angle varies
  // along it (measured 0.017 %); 6x above.
  EXPECT_NEAR(reaction / theta, 1.0, 1e-3);
}

TEST(Statics, HorizontalCantileverMatchesBeamTheory) {
  // Clamped along +x in air, EI = 1e6 N m^2, L = 10 m under its weight w = m' g: the tip sinks by
  // w L^4 / (8 EI) = 7.4 mm (7e-4 of L: the geometry is linear to ~1e-6). The springs' placement makes
  // the discrete cantilever second order (docs/MODEL.md section 5: 0.06 % at n = 40).
  const double ei = 1.0e6, length = 10.0, w = kMassPerLength * kGravity;
  const double exact = w * std::pow(length, 4) / (8.0 * ei);
  ChainDynamics chain(cable(length, 40, {"cable.stiffness={model: bending, bending_rigidity: 1.0e6, torsional_rigidity: 500}",
                                         "fluid.density=0", "base.direction=[1, 0, 0]"}));
  const StaticSolution s = solve(chain, StaticProblem(), "cantilever");
  const double error = s.tip_position.z() / exact - 1.0;
  std::cout << "cantilever n = 40: tip sag " << s.tip_position.z() << " m, w L^4/(8 EI) = " << exact << " m, error "
            << 100 * error << " %, tip x " << s.tip_position.x() << " m\n";
  // The discrete cantilever's second-order error (measured 0.062 % at n = 40, as docs/MODEL.md says); 5x.
  EXPECT_LT(std::abs(error), 3e-3);
  // Every joint's twist zero, from the clamp's frame on.
  const LinkProperties& p = chain.properties();
  for (int k = 0; k < chain.links(); ++k) {
    const JointGeometry g = jointGeometry(k > 0 ? Eigen::Vector3d(s.axes.col(k - 1)) : p.clamp_axis, s.axes.col(k),
                                          s.twists(k), k > 0 ? s.twists(k - 1) : p.clamp_twist);
    EXPECT_NEAR(g.twist, 0.0, 1e-12) << "joint " << k;
  }
  EXPECT_LT(restAcceleration(chain, s, StaticProblem()), kRestTolerance);
}

TEST(Statics, StiffCableInACurrentIsAnEquilibriumOfTheDynamics) {
  // The default cable made stiff (EI = 200 N m^2: bending matters over a few metres) hanging from a
  // vertical clamp in a 0.5 m/s current at an angle, free load: no closed form, but at the solved shape
  // the dynamics' angular accelerations vanish.
  ChainDynamics chain(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml",
                                     {"cable.stiffness={model: bending, bending_rigidity: 200, torsional_rigidity: 100}",
                                      "fluid.current=[0.4, 0.3, 0]", "load.drag_area=0.3"}));
  const StaticSolution s = solve(chain, StaticProblem(), "stiff cable in a current");
  const double a = restAcceleration(chain, s, StaticProblem());
  std::cout << "stiff cable in a current: largest angular acceleration " << a << " g/l, top angle "
            << std::acos(s.axes(2, 0)) << " rad, tip " << s.tip_position.transpose() << " m\n";
  EXPECT_LT(a, kRestTolerance);
}

TEST(Statics, CoupledTipInACurrentIsAnEquilibriumOfTheDynamics) {
  // The default cable anchored (exactly) 30 m across and 35 m down, in a depth
  // profile of current: the limp shape there, checked against the dynamics.
  ChainDynamics chain(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml",
                                     {"load.mode=anchored", "fluid.current=[0, 0, 0]", "fluid.current_profile=[[0, 0.5, 0.1, 0], [40, 0.1, 0, 0]]"}));
  StaticProblem problem;
  problem.tip_coupled = true;
  problem.target_position = Eigen::Vector3d(30.0, 0.0, 35.0);
  const StaticSolution s = solve(chain, problem, "anchored in a profile");
  const double a = restAcceleration(chain, s, problem);
  std::cout << "anchored: largest angular acceleration " << a << " g/l, tip " << s.tip_position.transpose()
            << " m, top tension " << s.tension(0) << " N\n";
  EXPECT_LT(a, kRestTolerance);
}

TEST(Statics, TargetOutOfReachHasNoEquilibrium) {
  ChainDynamics chain(cable(100.0, 20, {"fluid.density=0", "load.mode=anchored"}));
  StaticProblem problem;
  problem.tip_coupled = true;
  problem.target_position = Eigen::Vector3d(100.0, 0.0, 60.0);
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), problem);
  std::cout << "out of reach: " << s.message << "\n";
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.message.find("no equilibrium"), std::string::npos);
  EXPECT_NE(s.message.find("116.6"), std::string::npos);  // the distance, sqrt(100^2 + 60^2) m
}

TEST(Statics, PaperSpringsAreRefused) {
  ChainDynamics chain(cable(10.0, 5, {"cable.stiffness={model: paper, elevation: 10}"}));
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), StaticProblem());
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.message.find("paper"), std::string::npos);
}

TEST(Statics, StiffAnchoredCableIsAnEquilibriumOfTheDynamics) {
  // Stiff (EI = 200 N m^2) and anchored: Newton has to bend the limp shot start into shape, the
  // clamp holding the top straight down while the anchor pulls the tip sideways. A known slow case:
  // far from the answer the line search takes ~1/20 of each Newton step (81 iterations here at n = 25,
  // 13 at n = 100, 7 at n = 1000), then converges quadratically.
  ChainDynamics chain(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/default.yaml",
                                     {"cable.stiffness={model: bending, bending_rigidity: 200, torsional_rigidity: 100}",
                                      "load.mode=anchored"}));
  StaticProblem problem;
  problem.tip_coupled = true;
  problem.target_position = Eigen::Vector3d(30.0, 0.0, 35.0);
  const StaticSolution s = solve(chain, problem, "stiff, anchored", 100);
  const double a = restAcceleration(chain, s, problem);
  std::cout << "stiff, anchored: largest angular acceleration " << a << " g/l, top angle " << std::acos(s.axes(2, 0))
            << " rad, tip " << s.tip_position.transpose() << " m\n";
  EXPECT_LT(a, kRestTolerance);
  EXPECT_LT(std::acos(std::min(1.0, s.axes(2, 0))), 0.3);  // the clamp keeps the top near vertical
}

TEST(Statics, LargeDeflectionCantileverIsAnEquilibriumOfTheDynamics) {
  // A soft horizontal cantilever (EI = 20 N m^2, w L^4 / (8 EI) = 368 m: linear theory meaningless)
  // droops to hang nearly down: far from the straight start, so Newton may need the continuation.
  ChainDynamics chain(cable(10.0, 40, {"cable.stiffness={model: bending, bending_rigidity: 20, torsional_rigidity: 10}",
                                       "fluid.density=0", "base.direction=[1, 0, 0]"}));
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), StaticProblem());
  std::cout << "large deflection: converged " << s.converged << " in " << s.iterations << " iterations, residual "
            << s.residual << ", tip " << s.tip_position.transpose() << " m " << s.message << "\n";
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_GT(s.tip_position.z(), 5.0);  // droops far below the clamp
  EXPECT_LT(restAcceleration(chain, s, StaticProblem()), kRestTolerance);
}
