// The generated paper model: structure of M, positions of the seed paper's Eq. (2), and consistency of
// M, h and G with the energies they come from. The symbolic Euler-Lagrange comparison lives in
// test_sympy_reference.py; these checks use only finite differences of independently computed energies.
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/states.h"
#include "cable_dynamics/dynamics/paper_model.h"

using namespace cable_dynamics;

namespace {

LinkProperties makeProperties(int n, double load_mass = 4.0) {
  CableParams p = loadConfigString(R"(
cable: {links: 1, length: 1.0, diameter: 0.03, mass_per_length: 0.8}
load: {mass: 4.0, volume: 0.002}
fluid: {density: 1025.0}
)",
                                   {"cable.links=" + std::to_string(n), "load.mass=" + std::to_string(load_mass)});
  // Unequal links exercise the per-link bookkeeping.
  for (int k = 0; k < n; ++k) p.link_lengths[k] = 0.5 + 0.1 * k;
  return deriveLinkProperties(p);
}

struct Terms {
  explicit Terms(int dof) : M(dof, dof), h(dof), G(dof) {}
  Eigen::MatrixXd M;
  Eigen::VectorXd h, G;
};

/// Rotation of link k from the paper's Euler angles: Rz(-psi) Rx(-te) Rz(-phi).
Eigen::Matrix3d linkRotation(double te, double psi, double phi) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(-psi, Eigen::Vector3d::UnitZ()) * AngleAxisd(-te, Eigen::Vector3d::UnitX()) *
          AngleAxisd(-phi, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/// Kinetic energy from finite differences of positions and rotations along qd (independent of M).
double kineticEnergyByDifferences(const PaperModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const int n = model.links();
  const double eps = 1e-6;
  const Eigen::VectorXd qp = q + eps * qd, qm = q - eps * qd;
  Eigen::Matrix3Xd cp(3, n), cm(3, n), ep(3, n + 1), em(3, n + 1);
  model.centresOfMass(qp, cp);
  model.centresOfMass(qm, cm);
  model.linkEnds(qp, ep);
  model.linkEnds(qm, em);
  const LinkProperties& p = model.properties();
  double t = 0.5 * p.load_mass * ((ep.col(n) - em.col(n)) / (2 * eps)).squaredNorm();
  double psi_p = 0, psi_m = 0, phi_p = 0, phi_m = 0;
  for (int k = 0; k < n; ++k) {
    t += 0.5 * p.mass(k) * ((cp.col(k) - cm.col(k)) / (2 * eps)).squaredNorm();
    psi_p += qp(3 * k + 1), psi_m += qm(3 * k + 1), phi_p += qp(3 * k + 2), phi_m += qm(3 * k + 2);
    const Eigen::Matrix3d rp = linkRotation(qp(3 * k), psi_p, phi_p), rm = linkRotation(qm(3 * k), psi_m, phi_m);
    const Eigen::Matrix3d r = 0.5 * (rp + rm);
    const Eigen::Matrix3d skew = ((rp - rm) / (2 * eps)) * r.transpose();
    const Eigen::Vector3d omega(skew(2, 1), skew(0, 2), skew(1, 0));
    const Eigen::Vector3d axis = r.col(2).normalized();
    const double spin = omega.dot(axis);
    t += 0.5 * p.inertia_transverse(k) * (omega.squaredNorm() - spin * spin) + 0.5 * p.inertia_polar(k) * spin * spin;
  }
  return t;
}

/// Potential energy from the positions alone: V = -g (sum ms_k z_k + ms_load z_load), z down.
double potentialByPositions(const PaperModel& model, const Eigen::VectorXd& q) {
  const int n = model.links();
  const LinkProperties& p = model.properties();
  Eigen::Matrix3Xd com(3, n), ends(3, n + 1);
  model.centresOfMass(q, com);
  model.linkEnds(q, ends);
  double v = -p.gravity * p.load_submerged_mass * ends(2, n);
  for (int k = 0; k < n; ++k) v -= p.gravity * p.submerged_mass(k) * com(2, k);
  return v;
}

}  // namespace

TEST(PaperModel, PositionsFollowSeedEquation2) {
  for (int n : {1, 3, 7}) {
    PaperModel model(makeProperties(n));
    Eigen::VectorXd q, qd;
    randomState(n, 11u + n, q, qd);
    Eigen::Matrix3Xd com(3, n), ends(3, n + 1);
    model.centresOfMass(q, com);
    model.linkEnds(q, ends);
    const Eigen::VectorXd& l = model.properties().length;
    for (int k = 0; k < n; ++k) {
      // Eq. (2) written out literally: sums of the azimuths, elevation absolute.
      auto psi = [&](int j) {
        double s = 0;
        for (int i = 0; i <= j; ++i) s += q(3 * i + 1);
        return s;
      };
      double x = l(k) / 2 * std::sin(q(3 * k)) * std::sin(psi(k));
      double y = l(k) / 2 * std::sin(q(3 * k)) * std::cos(psi(k));
      double z = l(k) / 2 * std::cos(q(3 * k));
      for (int j = 0; j < k; ++j) {
        x += l(j) * std::sin(q(3 * j)) * std::sin(psi(j));
        y += l(j) * std::sin(q(3 * j)) * std::cos(psi(j));
        z += l(j) * std::cos(q(3 * j));
      }
      EXPECT_NEAR(com(0, k), x, 1e-14);
      EXPECT_NEAR(com(1, k), y, 1e-14);
      EXPECT_NEAR(com(2, k), z, 1e-14);
      // The link's far end is one full link beyond its base end, the CoM halfway.
      EXPECT_NEAR((ends.col(k + 1) - ends.col(k)).norm(), l(k), 1e-14);
      EXPECT_NEAR((0.5 * (ends.col(k) + ends.col(k + 1)) - com.col(k)).norm(), 0.0, 1e-14);
    }
  }
}

TEST(PaperModel, MassMatrixSymmetricPositiveDefiniteAwayFromVertical) {
  for (int n : {1, 2, 5, 25}) {
    PaperModel model(makeProperties(n));
    Terms t(3 * n);
    for (unsigned seed = 1; seed <= 5; ++seed) {
      Eigen::VectorXd q, qd;
      randomState(n, seed, q, qd);
      model.compute(q, qd, t.M, t.h, t.G);
      EXPECT_LT((t.M - t.M.transpose()).cwiseAbs().maxCoeff(), 1e-12 * t.M.cwiseAbs().maxCoeff()) << "n=" << n;
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(t.M);
      EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << "n=" << n << " seed=" << seed;
      EXPECT_TRUE(t.M.allFinite() && t.h.allFinite() && t.G.allFinite());
    }
  }
}

TEST(PaperModel, MassMatrixSingularAtZeroElevation) {
  // At te_k = 0 azimuth and torsion of link k are the same rotation: M has a null direction per link.
  const int n = 3;
  PaperModel model(makeProperties(n));
  Terms t(3 * n);
  model.compute(Eigen::VectorXd::Zero(3 * n), Eigen::VectorXd::Zero(3 * n), t.M, t.h, t.G);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(t.M);
  EXPECT_LT(std::abs(eig.eigenvalues()(0)), 1e-12 * eig.eigenvalues().maxCoeff());
  Eigen::VectorXd null_direction = Eigen::VectorXd::Zero(3 * n);
  null_direction(3 * 1 + 1) = 1.0;   // a_2 = +1
  null_direction(3 * 1 + 2) = -1.0;  // t_2 = -1: link 2 turns about the vertical, then untwists
  null_direction(3 * 2 + 1) = -1.0;  // a_3 = -1 keeps psi_3 as it was
  null_direction(3 * 2 + 2) = 1.0;   // t_3 = +1 keeps phi_3 as it was
  EXPECT_LT((t.M * null_direction).norm(), 1e-12 * t.M.norm());
}

TEST(PaperModel, KineticEnergyMatchesPositionsAndRotations) {
  for (int n : {1, 2, 6}) {
    PaperModel model(makeProperties(n));
    Terms t(3 * n);
    for (unsigned seed = 1; seed <= 4; ++seed) {
      Eigen::VectorXd q, qd;
      randomState(n, 100u + seed, q, qd);
      model.compute(q, qd, t.M, t.h, t.G);
      const double from_matrix = 0.5 * qd.dot(t.M * qd);
      const double from_motion = kineticEnergyByDifferences(model, q, qd);
      // Central differences with eps = 1e-6: truncation ~eps^2, rounding ~1e-16/eps ~ 1e-10 relative.
      EXPECT_NEAR(from_matrix, from_motion, 1e-8 * from_matrix) << "n=" << n;
    }
  }
}

TEST(PaperModel, GravityIsGradientOfPotential) {
  for (int n : {1, 4}) {
    PaperModel model(makeProperties(n));
    Terms t(3 * n);
    Eigen::VectorXd q, qd;
    randomState(n, 7u, q, qd);
    model.compute(q, qd, t.M, t.h, t.G);
    EXPECT_NEAR(model.potentialEnergy(q), potentialByPositions(model, q), 1e-12);
    for (int i = 0; i < 3 * n; ++i) {
      const double eps = 1e-6;
      Eigen::VectorXd qp = q, qm = q;
      qp(i) += eps;
      qm(i) -= eps;
      const double grad = (potentialByPositions(model, qp) - potentialByPositions(model, qm)) / (2 * eps);
      EXPECT_NEAR(t.G(i), grad, 1e-7 * std::max(1.0, t.G.cwiseAbs().maxCoeff())) << coordinateName(i);
    }
  }
}

TEST(PaperModel, CoriolisTermsConsistentWithMassMatrixRate) {
  // For h = C(q, q') q' from a Lagrangian, q'^T h = 1/2 q'^T (dM/dt) q' (M' - 2C is skew-symmetric),
  // and more strictly h = M' q' - 1/2 d(q'^T M q')/dq. Both are checked with dM from finite differences.
  for (int n : {1, 3}) {
    PaperModel model(makeProperties(n));
    const int dof = 3 * n;
    Terms t(dof), tp(dof), tm(dof);
    Eigen::VectorXd q, qd;
    randomState(n, 21u, q, qd);
    model.compute(q, qd, t.M, t.h, t.G);
    const double eps = 1e-6;
    model.compute(q + eps * qd, qd, tp.M, tp.h, tp.G);
    model.compute(q - eps * qd, qd, tm.M, tm.h, tm.G);
    const Eigen::MatrixXd m_rate = (tp.M - tm.M) / (2 * eps);
    Eigen::VectorXd expected = m_rate * qd;
    for (int i = 0; i < dof; ++i) {
      Eigen::VectorXd qp = q, qm = q;
      qp(i) += eps;
      qm(i) -= eps;
      model.compute(qp, qd, tp.M, tp.h, tp.G);
      model.compute(qm, qd, tm.M, tm.h, tm.G);
      expected(i) -= 0.5 * (qd.dot(tp.M * qd) - qd.dot(tm.M * qd)) / (2 * eps);
    }
    const double scale = std::max(1e-3, t.h.cwiseAbs().maxCoeff());
    EXPECT_LT((t.h - expected).cwiseAbs().maxCoeff(), 1e-6 * scale) << "n=" << n;
    EXPECT_NEAR(qd.dot(t.h), 0.5 * qd.dot(m_rate * qd), 1e-6 * scale);
  }
}

TEST(PaperModel, SingleLinkIsACompoundPendulum) {
  const LinkProperties p = makeProperties(1, 2.5);
  PaperModel model(p);
  Terms t(3);
  Eigen::Vector3d q(0.4, 0.3, -0.2), qd = Eigen::Vector3d::Zero();
  model.compute(q, qd, t.M, t.h, t.G);
  const double l = p.length(0), m = p.mass(0);
  EXPECT_NEAR(t.M(0, 0), m * l * l / 4 + p.inertia_transverse(0) + p.load_mass * l * l, 1e-13);
  EXPECT_NEAR(t.G(0), p.gravity * (p.submerged_mass(0) * l / 2 + p.load_submerged_mass * l) * std::sin(0.4), 1e-13);
  EXPECT_NEAR(t.M(2, 2), p.inertia_polar(0), 1e-15);
}
