// The singularity-free equations of motion against the generated paper model: same accelerations at
// random states away from the vertical (the paper model is itself checked against sympy), the same
// spring forces, and the statics of a hanging cable.
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/dynamics/elastic_joints.h"
#include "cable_dynamics/dynamics/paper_model.h"
#include "cable_dynamics/params/states.h"

using namespace cable_dynamics;

namespace {

CableParams makeParams(int n, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> overrides = {"cable.links=" + std::to_string(n)};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  CableParams p = loadConfigString(R"(
cable: {links: 1, length: 1.0, diameter: 0.04, mass_per_length: 0.8}
load: {mass: 2.0, volume: 0.0}
fluid: {density: 0.0}
)",
                                   overrides);
  for (int k = 0; k < n; ++k) p.link_lengths[k] = 0.6 + 0.15 * k;  // unequal links
  return p;
}

/// Paper accelerations q'' from M q'' = -(h + G + elastic + D q').
Eigen::VectorXd paperAccelerations(const CableParams& params, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const LinkProperties props = deriveLinkProperties(params);
  const int dof = 3 * props.n;
  PaperModel model(props);
  ElasticJoints joints(props);
  Eigen::MatrixXd M(dof, dof), D(dof, dof);
  Eigen::VectorXd h(dof), G(dof), elastic(dof);
  model.compute(q, qd, M, h, G);
  joints.force(q, elastic);
  joints.damping(D);
  return M.ldlt().solve(-(h + G + elastic + D * qd));
}

/// Angular accelerations implied by paper accelerations: omega = -psi' e_z - te' n - phi' u, differentiated:
/// omega' = -psi'' e_z - te'' n - phi'' u + te' psi' m - phi' (te' e + psi' w).
Eigen::VectorXd omegaRateFromPaper(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
  const int n = static_cast<int>(q.size()) / 3;
  Eigen::VectorXd out(3 * n);
  double psi = 0, psi_rate = 0, phi_rate = 0, psi_acc = 0, phi_acc = 0;
  for (int k = 0; k < n; ++k) {
    psi += q(3 * k + 1);
    psi_rate += qd(3 * k + 1);
    phi_rate += qd(3 * k + 2);
    psi_acc += qdd(3 * k + 1);
    phi_acc += qdd(3 * k + 2);
    const double te = q(3 * k), te_rate = qd(3 * k), te_acc = qdd(3 * k);
    const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d u = linkAxis(te, psi);
    const Eigen::Vector3d nv(std::cos(psi), -std::sin(psi), 0.0), mv(std::sin(psi), std::cos(psi), 0.0);
    const Eigen::Vector3d e(std::cos(te) * std::sin(psi), std::cos(te) * std::cos(psi), -std::sin(te));
    const Eigen::Vector3d w = std::sin(te) * nv;
    out.segment<3>(3 * k) = -psi_acc * ez - te_acc * nv - phi_acc * u + te_rate * psi_rate * mv -
                            phi_rate * (te_rate * e + psi_rate * w);
  }
  return out;
}

/// `p` with its formulation set to `formulation`.
CableParams formulated(CableParams p, Formulation formulation) {
  p.simulation.formulation = formulation;
  return p;
}

/// Ends with the base displaced, moving and accelerating (paper frame) [m, m/s, m/s^2].
EndInputs movingBase() {
  EndInputs ends;
  ends.base_position = Eigen::Vector3d(0.1, -0.2, 0.05);
  ends.base_velocity = Eigen::Vector3d(0.3, 0.1, -0.2);
  ends.base_acceleration = Eigen::Vector3d(-0.5, 0.8, 1.1);
  return ends;
}

void expectSameAccelerations(const CableParams& params, unsigned seed) {
  for (bool recursive : {false, true}) {
    SCOPED_TRACE(recursive ? "recursive formulation" : "dense (paper) formulation");
  const int n = params.links;
  CableParams formulated = params;
  formulated.simulation.formulation = recursive ? Formulation::kRecursive : Formulation::kPaper;
  ChainDynamics chain(formulated);
  Eigen::VectorXd q, qd;
  randomState(n, seed, q, qd);
  Eigen::VectorXd x;
  chain.stateFromPaper(q, qd, x);
  Eigen::VectorXd psi(n);
  double sum = 0;
  for (int k = 0; k < n; ++k) psi(k) = (sum += q(3 * k + 1));
  chain.setAzimuthReference(psi);
  ChainOutputs out;
  ASSERT_TRUE(chain.evaluate(x, EndInputs(), out));
  const Eigen::VectorXd expected = omegaRateFromPaper(q, qd, paperAccelerations(params, q, qd));
  const double scale = expected.cwiseAbs().maxCoeff();
  // Both sides are exact formulas; 1e-9 leaves room for the condition number of the two solves.
  EXPECT_LT((out.omega_rate - expected).cwiseAbs().maxCoeff(), 1e-9 * scale) << "seed " << seed;
  // The round trip paper -> state -> paper is exact away from the vertical.
  Eigen::VectorXd q2(3 * n), qd2(3 * n);
  chain.paperCoordinates(x, q2, qd2);
  for (int i = 0; i < 3 * n; ++i) {
    EXPECT_NEAR(std::remainder(q2(i) - q(i), 2 * M_PI), 0.0, 1e-12) << coordinateName(i);
    EXPECT_NEAR(qd2(i), qd(i), 1e-12) << coordinateName(i);
  }
  }
}

}  // namespace

TEST(ChainDynamics, AgreesWithPaperModelWithoutSprings) {
  for (int n : {1, 2, 5}) {
    for (unsigned seed = 1; seed <= 3; ++seed) expectSameAccelerations(makeParams(n), seed + 10 * n);
  }
}

TEST(ChainDynamics, AgreesWithPaperModelWithPaperSpringsAndDampers) {
  const CableParams p = makeParams(4, {"cable.stiffness={model: paper, elevation: 3.0, azimuth: 2.0, torsion: 0.5}",
                                       "cable.damping={elevation: 0.3, azimuth: 0.2, torsion: 0.01}"});
  for (unsigned seed = 1; seed <= 4; ++seed) expectSameAccelerations(p, seed);
}

TEST(ChainDynamics, AgreesWithPaperModelWithBendingSprings) {
  const CableParams p = makeParams(4, {"cable.stiffness={model: bending, elevation: 3.0, torsion: 0.5}"});
  for (unsigned seed = 1; seed <= 4; ++seed) expectSameAccelerations(p, seed);
}

TEST(ChainDynamics, AgreesWithPaperModelWithATiltedClampAndWithAPin) {
  // The base clamp along a tilted direction: joint 1 bends and twists link 1 against it, in the
  // dynamics (on link axes) and in ElasticJoints (on the paper angles, by automatic differentiation).
  for (const char* base : {"base={direction: [0.3, -0.5, -0.8]}", "base={direction: [1, 0, 0]}", "base={fixity: pinned}"}) {
    SCOPED_TRACE(base);
    const CableParams p = makeParams(4, {"cable.stiffness={model: bending, elevation: 3.0, torsion: 0.5}", base});
    for (unsigned seed = 1; seed <= 4; ++seed) expectSameAccelerations(p, seed);
  }
}

TEST(ChainDynamics, RecursiveAndDenseFormulationsAgreeWithEveryForce) {
  // Fluid drag in a sheared current (drag point by point) and in a uniform one (drag by the uniform
  // shortcut), added mass, a moving base, springs, dampers and the load coupling. The two formulations
  // share only the forces' definitions: the dense one solves the mass matrix and sums Newton's law
  // outboard for the joint forces and the added-mass power, the recursive one gets all three from its
  // two passes. So the accelerations, the tensions and the rate of the dissipated energy must agree.
  for (const char* current : {"fluid.current_profile=[[0, 1.2, -0.3, 0.1], [6, 0.4, 0.2, 0]]",
                              "fluid.current=[0.9, -0.4, 0.2]"}) {
    const CableParams p = makeParams(7, {"fluid.density=1025", current,
                                         "load={mass: 3.0, volume: 0.001, mode: attached, drag_area: 0.2, added_mass: 1.5}",
                                         "cable.stiffness={model: bending, elevation: 2.0, torsion: 0.3}",
                                         "cable.damping={elevation: 0.2, torsion: 0.05}"});
    ChainDynamics dense(formulated(p, Formulation::kPaper)), recursive(formulated(p, Formulation::kRecursive));
    EndInputs ends = movingBase();
    ends.load_coupled = true;
    ends.target_position = Eigen::Vector3d(2.0, 1.0, 4.0);
    ends.target_velocity = Eigen::Vector3d(0.2, 0.0, 0.1);
    for (unsigned seed = 1; seed <= 5; ++seed) {
      Eigen::VectorXd q, qd, x;
      randomState(7, seed, q, qd);
      dense.stateFromPaper(q, qd, x);
      ChainOutputs a, b;
      ASSERT_TRUE(dense.evaluate(x, ends, a));
      ASSERT_TRUE(recursive.evaluate(x, ends, b));
      const double scale = a.omega_rate.cwiseAbs().maxCoeff();
      EXPECT_LT((a.omega_rate - b.omega_rate).cwiseAbs().maxCoeff(), 1e-9 * scale) << current << " seed " << seed;
      EXPECT_LT((a.tension - b.tension).cwiseAbs().maxCoeff(), 1e-9 * a.tension.cwiseAbs().maxCoeff())
          << current << " seed " << seed;
      EXPECT_LT((a.joint_force - b.joint_force).cwiseAbs().maxCoeff(), 1e-9 * a.joint_force.cwiseAbs().maxCoeff())
          << current << " seed " << seed;
      Eigen::VectorXd rate_a(x.size()), rate_b(x.size());
      ASSERT_TRUE(dense.derivative(x, ends, rate_a));
      ASSERT_TRUE(recursive.derivative(x, ends, rate_b));
      const int dissipated = StateLayout::dissipated(7), work = StateLayout::workInput(7);
      EXPECT_NEAR(rate_a(dissipated), rate_b(dissipated), 1e-9 * std::abs(rate_a(dissipated))) << current;
      EXPECT_NEAR(rate_a(work), rate_b(work), 1e-9 * std::abs(rate_a(work)) + 1e-12) << current;
    }
  }
}

TEST(ChainDynamics, RecursiveAndDenseFormulationsAgreeWithAnRovBody) {
  // An ROV body on the tip (load.mode body) off its centre of gravity, in a current, under a thrust and
  // turning: the dense formulation takes the body as a 3x3 mass and bias at the tip in its mass matrix and
  // its right-hand side, the recursion in its inward pass (rov_body.h); the accelerations, the tensions,
  // the body's own acceleration and the balance's rates must agree.
  const CableParams p = makeParams(6, {"fluid.density=1025", "fluid.current=[0.6, -0.3, 0.1]",
                                       "load={mass: 11.5, volume: 0.0114, mode: body, attachment: [-0.2, 0.05, 0.1], "
                                       "body: {inertia: [0.16, 0.2, 0.25], center_of_gravity: [0.01, 0.0, -0.02], "
                                       "center_of_buoyancy: [0.0, 0.0, 0.02], added_mass: [5.5, 12.7, 14.57, 0.12, 0.12, 0.12], "
                                       "linear_damping: [4.03, 6.22, 5.18, 0.07, 0.07, 0.07], "
                                       "quadratic_damping: [18.18, 21.66, 36.99, 1.55, 1.55, 1.55]}}",
                                       "cable.stiffness={model: bending, bending_rigidity: 0.5, torsional_rigidity: 0.2}"});
  ChainDynamics dense(formulated(p, Formulation::kPaper)), recursive(formulated(p, Formulation::kRecursive));
  EndInputs ends = movingBase();
  ends.body_thrust << 12.0, -5.0, 3.0, 0.4, -0.2, 0.6;
  const int n = 6, attitude = StateLayout::bodyAttitude(n), spin = StateLayout::bodyOmega(n);
  double largest[6] = {};  // over the seeds, relative: see the print below
  for (unsigned seed = 1; seed <= 5; ++seed) {
    Eigen::VectorXd q, qd, x;
    randomState(n, seed, q, qd);
    dense.stateFromPaper(q, qd, x);
    ASSERT_EQ(x.size(), dense.stateSize());
    x.segment<4>(attitude) = Eigen::Vector4d(0.3 + 0.1 * seed, 0.8, -0.2 * seed, 0.4).normalized();
    x.segment<3>(spin) = Eigen::Vector3d(0.5, -0.3 * seed, 0.2);
    ChainOutputs a, b;
    ASSERT_TRUE(dense.evaluate(x, ends, a));
    ASSERT_TRUE(recursive.evaluate(x, ends, b));
    Eigen::VectorXd rate_a(x.size()), rate_b(x.size());
    ASSERT_TRUE(dense.derivative(x, ends, rate_a));
    ASSERT_TRUE(recursive.derivative(x, ends, rate_b));
    const auto apart = [](const auto& u, const auto& v) { return (u - v).cwiseAbs().maxCoeff() / u.cwiseAbs().maxCoeff(); };
    // The body's attitude rate and angular acceleration, and the balance's rates (the body's fluid losses
    // and thrust power in them).
    const int dissipated = StateLayout::dissipated(n), work = StateLayout::workInput(n);
    const double seen[] = {apart(a.omega_rate, b.omega_rate), apart(a.tension, b.tension), apart(a.load_force, b.load_force),
                           apart(rate_a.segment<7>(attitude), rate_b.segment<7>(attitude)),
                           std::abs(rate_a(dissipated) - rate_b(dissipated)) / std::abs(rate_a(dissipated)),
                           std::abs(rate_a(work) - rate_b(work)) / std::abs(rate_a(work))};
    for (int i = 0; i < 6; ++i) largest[i] = std::max(largest[i], seen[i]);
  }
  std::cout << "[ body ] relative differences, largest over the seeds: angular accelerations " << largest[0]
            << ", tensions " << largest[1] << ", load force " << largest[2] << ", body's rates " << largest[3]
            << ", dissipation rate " << largest[4] << ", work rate " << largest[5] << "\n";
  // Round-off of two different sums of the same terms (the largest angular acceleration is 8e3 rad/s^2).
  // Measured: 7.3e-12, 3.1e-12, 3.6e-12, 8.8e-13, 3.4e-13, 1.6e-12; bounds 6-9x above.
  const double bounds[] = {5e-11, 2e-11, 2e-11, 5e-12, 3e-12, 1e-11};
  for (int i = 0; i < 6; ++i) EXPECT_LT(largest[i], bounds[i]) << i;
}

TEST(ChainDynamics, HangingCableCarriesTheWeightBelow) {
  // At rest straight down, the tension at joint k is the submerged weight of everything below it
  // (a heavy cable: 3 kg/m against 1.29 kg/m of displaced water).
  CableParams p = makeParams(6, {"fluid.density=1025", "load.volume=0.0005", "cable.mass_per_length=3.0"});
  ChainDynamics chain(p);
  Eigen::VectorXd x;
  chain.stateFromPaper(Eigen::VectorXd::Zero(18), Eigen::VectorXd::Zero(18), x);
  ChainOutputs out;
  ASSERT_TRUE(chain.evaluate(x, EndInputs(), out));
  const LinkProperties& props = chain.properties();
  double below = props.load_submerged_mass;
  for (int k = 5; k >= 0; --k) {
    below += props.submerged_mass(k);
    ASSERT_GT(below, 0.0);
    EXPECT_NEAR(out.tension(k), props.gravity * below, 1e-12 * props.gravity * below) << "joint " << k + 1;
  }
  EXPECT_NEAR(out.omega_rate.norm(), 0.0, 1e-12);
  EXPECT_NEAR(out.base_force.z(), props.gravity * below, 1e-9);
  EXPECT_NEAR(out.load_force.z(), -props.gravity * props.load_submerged_mass, 1e-9);
}

TEST(ChainDynamics, RejectsNonFiniteState) {
  ChainDynamics chain(makeParams(2));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(chain.stateSize()), xdot(chain.stateSize());
  x(2) = 1.0;
  x(9) = 1.0;
  x(5) = std::nan("");
  EXPECT_FALSE(chain.derivative(x, EndInputs(), xdot));
}
