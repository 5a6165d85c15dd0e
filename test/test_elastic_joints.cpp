// Joint springs: the paper's diagonal K, and the bending/twist energy checked against an independent
// computation from rotation matrices (bend angle between axes, twist after parallel transport).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/dynamics/elastic_joints.h"
#include "cable_dynamics/dynamics/joint_geometry.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/params/states.h"
#include "cable_dynamics/dynamics/paper_model.h"

using namespace cable_dynamics;

namespace {

LinkProperties makeProperties(int n, const std::string& stiffness) {
  return deriveLinkProperties(loadConfigString(R"(
cable: {links: 1, length: 1.0, diameter: 0.03, mass_per_length: 0.8}
)",
                                               {"cable.links=" + std::to_string(n), "cable.stiffness=" + stiffness,
                                                "cable.damping={elevation: 0.1, azimuth: 0.2, torsion: 0.3}"}));
}

Eigen::Matrix3d linkRotation(double te, double psi, double phi) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(-psi, Eigen::Vector3d::UnitZ()) * AngleAxisd(-te, Eigen::Vector3d::UnitX()) *
          AngleAxisd(-phi, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/// Twist of `child` relative to `parent` about the child's axis (body z), after carrying the parent's
/// frame onto the child's axis by the minimal rotation (parallel transport). The paper's Euler angles
/// turn a link by Rz(-phi), so a positive torsion is a negative rotation about body z: hence the minus.
double twistByParallelTransport(const Eigen::Matrix3d& parent, const Eigen::Matrix3d& child) {
  const Eigen::Quaterniond transport =
      Eigen::Quaterniond::FromTwoVectors(parent.col(2), child.col(2));
  const Eigen::Matrix3d carried = transport.toRotationMatrix() * parent;
  const Eigen::Matrix3d relative = carried.transpose() * child;  // a rotation about body z
  return -std::atan2(relative(1, 0), relative(0, 0));
}

double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/// The rotation matrices of links 1..n for coordinates q (the paper's Euler angles, psi and phi summed
/// along the chain from the base, which is straight down with no twist).
std::vector<Eigen::Matrix3d> linkRotations(const Eigen::VectorXd& q) {
  std::vector<Eigen::Matrix3d> r;
  double psi = 0, phi = 0;
  for (int k = 0; 3 * k < q.size(); ++k) {
    psi += q(3 * k + 1);
    phi += q(3 * k + 2);
    r.push_back(linkRotation(q(3 * k), psi, phi));
  }
  return r;
}

/// Each joint's twist as a continuous angle, not modulo 2 pi: the parallel-transport twist followed
/// along the straight path s q, s from 0 (every link straight down, untwisted: twist 0) to 1, in steps
/// small enough that it turns by far less than pi per step, its increments wrapped and summed. On that
/// path no two neighbouring axes are opposed (elevations below 1.3 rad each), so the twist is continuous.
std::vector<double> unwrappedTwists(const Eigen::VectorXd& q) {
  const int n = static_cast<int>(q.size()) / 3, steps = 400;
  std::vector<double> twist(n, 0.0), previous(n, 0.0);
  for (int i = 1; i <= steps; ++i) {
    const std::vector<Eigen::Matrix3d> r = linkRotations((double(i) / steps) * q);
    for (int k = 0; k < n; ++k) {
      const double now = twistByParallelTransport(k > 0 ? r[k - 1] : Eigen::Matrix3d::Identity(), r[k]);
      twist[k] += wrapAngle(now - previous[k]);
      previous[k] = now;
    }
  }
  return twist;
}

}  // namespace

TEST(ElasticJoints, PaperModelIsDiagonal) {
  const LinkProperties p = makeProperties(3, "{elevation: 2.0, azimuth: 3.0, torsion: 5.0}");
  ElasticJoints joints(p);
  Eigen::VectorXd q, qd;
  randomState(3, 4u, q, qd);
  Eigen::VectorXd f(9);
  Eigen::MatrixXd K(9, 9), D(9, 9);
  joints.force(q, f);
  joints.stiffness(q, K);
  joints.damping(D);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(f(3 * k), 2.0 * q(3 * k));
    EXPECT_DOUBLE_EQ(f(3 * k + 1), 3.0 * q(3 * k + 1));
    EXPECT_DOUBLE_EQ(f(3 * k + 2), 5.0 * q(3 * k + 2));
    EXPECT_DOUBLE_EQ(D(3 * k + 2, 3 * k + 2), 0.3);
  }
  EXPECT_DOUBLE_EQ((K - Eigen::MatrixXd(K.diagonal().asDiagonal())).norm(), 0.0);
  EXPECT_NEAR(joints.energy(q), 0.5 * q.dot(f), 1e-12);
}

TEST(ElasticJoints, BendAndTwistMatchRotationMatrices) {
  const int n = 5;
  const LinkProperties p = makeProperties(n, "{model: bending, elevation: 2.0, torsion: 5.0}");
  ElasticJoints joints(p);
  double widest_twist = 0.0;  // [rad]
  for (unsigned seed = 1; seed <= 6; ++seed) {
    Eigen::VectorXd q, qd;
    randomState(n, seed, q, qd);
    Eigen::Matrix3d parent = Eigen::Matrix3d::Identity();  // the base: axis straight down, no twist
    const std::vector<Eigen::Matrix3d> links = linkRotations(q);
    const std::vector<double> twists = unwrappedTwists(q);
    double psi = 0, expected_energy = 0, widest = 0;  // widest: the largest |twist| of this state [rad]
    for (int k = 0; k < n; ++k) {
      psi += q(3 * k + 1);
      const Eigen::Matrix3d& child = links[k];
      ASSERT_NEAR((child.col(2) - linkAxis(q(3 * k), psi)).norm(), 0.0, 1e-14);
      const double bend_expected = std::acos(std::clamp(parent.col(2).dot(child.col(2)), -1.0, 1.0));
      // The rotation matrices give the twist modulo 2 pi; its continuation from the untwisted state picks
      // the turn (the energy of a twist and of the same twist plus a full turn differ).
      const double twist_expected = twists[k];
      EXPECT_NEAR(wrapAngle(twist_expected - twistByParallelTransport(parent, child)), 0.0, 1e-12);
      double bend = 0, twist = 0;
      joints.bendAndTwist(q, k, bend, twist);
      EXPECT_NEAR(bend, bend_expected, 1e-9) << "joint " << k + 1;
      EXPECT_NEAR(twist, twist_expected, 1e-9) << "joint " << k + 1;
      widest = std::max(widest, std::abs(twist_expected));
      expected_energy += 0.5 * 2.0 * bend_expected * bend_expected + 0.5 * 5.0 * twist_expected * twist_expected;
      parent = child;
    }
    widest_twist = std::max(widest_twist, widest);
    EXPECT_NEAR(joints.energy(q), expected_energy, 1e-9 * expected_energy);
  }
  // The random states reach twists beyond pi, so the turn is checked, not only the angle modulo 2 pi.
  std::cout << "largest twist: " << widest_twist << " rad\n";
  EXPECT_GT(widest_twist, M_PI);
}

TEST(ElasticJoints, BendingForceAndStiffnessAreDerivativesOfEnergy) {
  const int n = 4;
  const LinkProperties p = makeProperties(n, "{model: bending, elevation: 2.0, torsion: 5.0}");
  ElasticJoints joints(p);
  const int dof = 3 * n;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Eigen::VectorXd q, qd;
    randomState(n, 30u + seed, q, qd);
    Eigen::VectorXd f(dof), fp(dof), fm(dof);
    Eigen::MatrixXd K(dof, dof);
    joints.force(q, f);
    joints.stiffness(q, K);
    const double eps = 1e-6;
    for (int i = 0; i < dof; ++i) {
      Eigen::VectorXd qp = q, qm = q;
      qp(i) += eps;
      qm(i) -= eps;
      // Central differences: error ~ eps^2 * third derivative + 1e-16 * energy / eps.
      EXPECT_NEAR(f(i), (joints.energy(qp) - joints.energy(qm)) / (2 * eps), 1e-7) << coordinateName(i);
      joints.force(qp, fp);
      joints.force(qm, fm);
      const Eigen::VectorXd column = (fp - fm) / (2 * eps);
      EXPECT_LT((K.col(i) - column).cwiseAbs().maxCoeff(), 1e-6) << coordinateName(i);
    }
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(ElasticJoints, BendingModelIsRegularAtTheVertical) {
  const int n = 3;
  const LinkProperties p = makeProperties(n, "{model: bending, elevation: 2.0, torsion: 5.0}");
  ElasticJoints joints(p);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * n), f(3 * n);
  Eigen::MatrixXd K(3 * n, 3 * n);
  joints.force(q, f);
  joints.stiffness(q, K);
  EXPECT_TRUE(f.allFinite());
  EXPECT_TRUE(K.allFinite());
  EXPECT_DOUBLE_EQ(f.norm(), 0.0);
  // Straight down, a twist of link 2 about the vertical may be written as azimuth or torsion: same energy.
  Eigen::VectorXd by_azimuth = q, by_torsion = q;
  by_azimuth(3 * 1 + 1) = 0.3;
  by_azimuth(3 * 2 + 1) = -0.3;
  by_torsion(3 * 1 + 2) = 0.3;
  by_torsion(3 * 2 + 2) = -0.3;
  EXPECT_NEAR(joints.energy(by_azimuth), joints.energy(by_torsion), 1e-14);
  EXPECT_NEAR(joints.energy(by_torsion), 2 * 0.5 * 5.0 * 0.3 * 0.3, 1e-14);
}

TEST(ElasticJoints, BendingEnergyInvariantToRotationAboutVertical) {
  // Rotating the whole cable about the vertical (a_1 -> a_1 + d, t_1 -> t_1 - d keeps the base twist)
  // leaves every bend and twist unchanged.
  const int n = 4;
  const LinkProperties p = makeProperties(n, "{model: bending, elevation: 2.0, torsion: 5.0}");
  ElasticJoints joints(p);
  Eigen::VectorXd q, qd;
  randomState(n, 77u, q, qd);
  Eigen::VectorXd turned = q;
  turned(1) += 0.7;
  turned(2) -= 0.7;
  EXPECT_NEAR(joints.energy(turned), joints.energy(q), 1e-12 * joints.energy(q));
}

// The twist across a joint whose two links rise steeply on either side of the vertical (paper frame: z
// down), bent across it: the arc between the axes passes over the upward pole, where the holonomy's
// arctangent changes branch (its solid angle is defined modulo 4 pi). Before the fix the twist jumped by
// 4 pi between y = +1e-9 and y = -1e-9 (two whole turns for the torsion spring, from frames that moved by
// nothing); now it is continuous: the two differ by round-off.
TEST(JointGeometry, TwistIsContinuousOverTheUpwardPole) {
  const auto axes = [](double y, Eigen::Vector3d& prev, Eigen::Vector3d& axis) {
    prev = Eigen::Vector3d(0.335, y, -0.942).normalized();
    axis = Eigen::Vector3d(-0.909, -y, -0.416).normalized();
  };
  Eigen::Vector3d prev, axis;
  axes(1e-9, prev, axis);
  const double holonomy = -jointGeometry(prev, axis, 0.0, 0.0).twist;  // the twist is sigma - sigma_prev - it
  for (const double held : {0.0, 0.3, -1.0}) {  // the joint's twist [rad] on the y > 0 side
    const double sigma = held + holonomy;
    axes(1e-9, prev, axis);
    const double before = jointGeometry(prev, axis, sigma, 0.0).twist;
    axes(-1e-9, prev, axis);
    const double after = jointGeometry(prev, axis, sigma, 0.0).twist;
    EXPECT_NEAR(before, held, 1e-9);
    EXPECT_NEAR(after, before, 1e-6) << "held " << held;  // before the fix: 4 pi apart
  }
  // And a twist a joint can hold is left as it is.
  const Eigen::Vector3d a(0.0, 0.0, 1.0), b = Eigen::Vector3d(0.1, 0.0, 1.0).normalized();
  EXPECT_NEAR(jointGeometry(a, b, 5.0, 0.0).twist, 5.0, 1e-12);
}

// The run that showed it: config/tms_tether.yaml (a soft tether's slack on the bottom, rising steeply to
// the ROV) in a current along x keeps its links in the x-z plane, on the pole's branch cut. It stopped at
// t = 0.097 s ("energy created": 526 J in one substep, even in 64 substeps); now it runs.
TEST(JointGeometry, TetherInACurrentAlongTheBranchCutRuns) {
  CableSimulator sim(loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/tms_tether.yaml",
                                    {"fluid.current=[0.3, 0, 0]"}));
  for (int i = 0; i < 500; ++i) {  // 0.5 s at 1 ms
    const StepReport report = sim.step();
    ASSERT_TRUE(report.ok) << report.message;
    ASSERT_EQ(report.substeps, 1) << "at t = " << sim.time();
  }
}
