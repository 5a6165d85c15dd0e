// The implicit integrator's recursion (stiff_articulated_body.cpp) against independent computations:
// - with zero weights and no extra right-hand side it is the ordinary equations of motion: the same
//   angular accelerations as ChainDynamics::derivative (the O(n) recursion of articulated_body.cpp, itself
//   held against the paper model and sympy);
// - its drag damping is the drag's velocity Jacobian: central differences of the external-load pass;
// - with weights it solves (M + c_D D + c_K K) a = rhs + c_K K r + D r, which this test assembles densely
//   from the dense formulation's mass matrix and generalized forces (dense_solver.cpp) and the Jacobian
//   blocks mapped through the links' velocity Jacobians, and solves by LU.
#include <cmath>
#include <iostream>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/dynamics/stiff_articulated_body.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/states.h"

using namespace cable_dynamics;

namespace {

/// A stiff cable (bending model with springs and dampers) in a current, with the tip coupled to a
/// target (`attached`) or free, unequal links.
CableParams stiffCable(int n, bool attached, bool in_water, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> o = {
      "cable.links=" + std::to_string(n),
      "cable.stiffness={model: bending, bending_rigidity: 300, torsional_rigidity: 150}",
      "cable.damping={elevation: 2.0, azimuth: 2.0, torsion: 0.3}",
      std::string("fluid.density=") + (in_water ? "1025" : "0"),
      "fluid.current=[0.8, -0.3, 0.1]",
  };
  if (attached) o.push_back("load={mass: 4.0, volume: 0.002, mode: attached, coupling: {stiffness: 5000, damping: 300}}");
  o.insert(o.end(), extra.begin(), extra.end());
  CableParams p = loadConfigString(
      "cable: {links: 1, length: 6.0, diameter: 0.04, mass_per_length: 1.5}\nload: {mass: 4.0, volume: 0.002}\n"
      "fluid: {drag_normal: 1.2, drag_tangential: 0.02, added_mass: 1.0}\n",
      o);
  for (int k = 0; k < n; ++k) p.link_lengths[k] = 0.4 + 0.05 * k;
  return p;
}

EndInputs endsFor(const CableParams& p, const Eigen::Vector3d& target) {
  EndInputs e;
  e.load_coupled = p.load.mode != LoadMode::kFree;
  e.target_position = target;
  e.target_velocity = Eigen::Vector3d(0.2, -0.1, 0.05);
  return e;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

TEST(ImplicitRecursion, ZeroWeightsGiveTheOrdinaryAccelerations) {
  for (bool attached : {false, true}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const int n = 9;
      const CableParams p = stiffCable(n, attached, true);
      ChainDynamics f(p);
      Eigen::VectorXd q, qd, x(f.stateSize()), xdot(f.stateSize());
      randomState(n, seed, q, qd);
      f.stateFromPaper(q, qd, x);
      const EndInputs ends = endsFor(p, Eigen::Vector3d(0.5, 0.2, 5.0));
      ASSERT_TRUE(f.derivative(x, ends, xdot));
      StiffArticulatedBody solver(n);
      f.computeLoads(x, ends);
      solver.linearize(f.model(), f.data(), ends);
      solver.clearExtra();
      solver.solve(f.model(), f.data(), 0.0, 0.0);
      double scale = 0.0, error = 0.0;
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d expected = xdot.segment<3>(StateLayout::omega(k));
        scale = std::max(scale, expected.norm());
        error = std::max(error, (solver.link(k).angular_acc - expected).norm());
      }
      // Same equations, a different elimination order (6x6 blocks here, 3x3 and 2x2 there): round-off.
      EXPECT_LT(error, 1e-9 * scale) << "seed " << seed << (attached ? " attached" : " free");
    }
  }
}

TEST(ImplicitRecursion, WeightsSolveTheDenseEffectiveSystem) {
  // In air and in water, and then with a seabed 1.5 m below the base (with friction: its damping joins the
  // drag's) and the tip clamped to the ROV: their blocks join the dense system as the drag's and the
  // joints' do.
  const std::vector<std::string> bed_and_clamp = {"seabed={depth: 1.5, friction: {axial: 0.3, lateral: 0.6}}",
                                                  "load.fixity=clamped", "load.direction=[0.3, 0.2, 0.9]"};
  for (int variant = 0; variant < 3; ++variant) {
    const bool in_water = variant > 0, grounded = variant == 2;
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const int n = 7, dof = 3 * n;
      const CableParams p = stiffCable(n, true, in_water, grounded ? bed_and_clamp : std::vector<std::string>{});
      ChainDynamics f(p);
      Eigen::VectorXd q, qd, x(f.stateSize()), rhs(dof);
      randomState(n, seed + 10, q, qd);
      f.stateFromPaper(q, qd, x);
      const EndInputs ends = endsFor(p, Eigen::Vector3d(0.3, -0.2, 4.0));
      const double cd = 0.004, ck = 0.004 * 0.004;  // theta h and (theta h)^2 at h = 8 ms
      const double a = 0.003, b = 0.7;              // the extra right-hand side's factors
      // Dense: M and the generalized forces (springs, dampers, drag, coupling, velocity terms).
      f.generalizedForces(x, ends, true, rhs);
      Eigen::MatrixXd system = f.massMatrix();
      const ChainData& data = f.data();
      StiffArticulatedBody solver(n);
      solver.linearize(f.model(), data, ends);
      // Velocity Jacobians: link k's base end moves at sum_{j<k} l_j omega_j x u_j = sum -l_j [u_j]x omega_j,
      // the tip at the sum over all links.
      std::vector<Eigen::MatrixXd> base(n + 1, Eigen::MatrixXd::Zero(3, dof));
      for (int k = 1; k <= n; ++k) {
        base[k] = base[k - 1];
        const Eigen::Vector3d u = data.links.get(&LinkBlock::u, k - 1);
        base[k].block<3, 3>(0, 3 * (k - 1)) += -f.deployed().get(&LinkConstants::length, k - 1) * skew(u);
      }
      Eigen::MatrixXd damping = Eigen::MatrixXd::Zero(dof, dof), stiffness = Eigen::MatrixXd::Zero(dof, dof);
      int contacts = 0;
      for (int k = 0; k < n; ++k) {
        const StiffLinkTerms& t = solver.link(k);
        // Joint k on the relative rotation of link k to link k-1 (to the clamp at rest for k = 0).
        Eigen::MatrixXd select = Eigen::MatrixXd::Zero(3, dof);
        select.block<3, 3>(0, 3 * k).setIdentity();
        if (k > 0) select.block<3, 3>(0, 3 * (k - 1)) = -Eigen::Matrix3d::Identity();
        stiffness += select.transpose() * t.joint_stiffness * select;
        damping += select.transpose() * t.joint_damping * select;
        // The link's geometric stiffness across it, and its drag over (omega_k, v_base,k).
        const Eigen::Vector3d u = t.axis;
        stiffness.block<3, 3>(3 * k, 3 * k) += t.geometric * (Eigen::Matrix3d::Identity() - u * u.transpose());
        Eigen::MatrixXd spatial(6, dof);
        spatial.topRows(3) = Eigen::MatrixXd::Zero(3, dof);
        spatial.topRows(3).block<3, 3>(0, 3 * k).setIdentity();
        spatial.bottomRows(3) = base[k];
        Eigen::Matrix<double, 6, 6> drag, contact;
        drag << t.drag_rr, t.drag_rv, t.drag_rv.transpose(), t.drag_vv;
        damping += spatial.transpose() * drag * spatial;
        contact << solver.contact(k).rr, solver.contact(k).rv, solver.contact(k).rv.transpose(), solver.contact(k).vv;
        stiffness += spatial.transpose() * contact * spatial;
        if (grounded) contacts += t.in_contact ? 1 : 0;
      }
      // A clamped tip: on the last link's rotation (the clamp at rest here).
      stiffness.block<3, 3>(3 * (n - 1), 3 * (n - 1)) += solver.tipClampStiffness();
      damping.block<3, 3>(3 * (n - 1), 3 * (n - 1)) += solver.tipClampDamping();
      // The load: coupling and drag at the tip.
      const LoadConstants& load = f.model().load();
      stiffness += load.coupling_stiffness * base[n].transpose() * base[n];
      Eigen::Matrix3d load_drag = Eigen::Matrix3d::Zero();
      if (in_water && load.drag_area > 0.0) {
        const Eigen::Vector3d v = data.current.at(data.tip_position.z()) - data.tip_velocity;
        const double c = 0.5 * f.model().fluidDensity() * load.drag_area;
        load_drag = c * (v.norm() * Eigen::Matrix3d::Identity() + v * v.transpose() / v.norm());
      }
      damping += base[n].transpose() * (load.coupling_damping * Eigen::Matrix3d::Identity() + load_drag) * base[n];
      system += cd * damping + ck * stiffness;
      // An arbitrary rotation r: the extra right-hand side a K r + b D r, with the translations D reads
      // taken consistently from r.
      Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(dof, -1.0, 1.3).array().sin();
      Eigen::Matrix3Xd rotation(3, n), translation(3, n);
      for (int k = 0; k < n; ++k) {
        rotation.col(k) = r.segment<3>(3 * k);
        translation.col(k) = base[k] * r;
      }
      const Eigen::Vector3d tip = base[n] * r;
      const Eigen::VectorXd plain = f.massMatrix().partialPivLu().solve(rhs);
      const Eigen::VectorXd dense = system.partialPivLu().solve(rhs + a * (stiffness * r) + b * (damping * r));
      // The terms matter here (else the comparison below would not test them).
      EXPECT_GT((dense - plain).lpNorm<Eigen::Infinity>(), 1e-3 * dense.lpNorm<Eigen::Infinity>());
      // The recursion, at the same state.
      f.computeLoads(x, ends);
      solver.linearize(f.model(), f.data(), ends);
      solver.clearExtra();
      solver.addJacobianTimes(f.model(), f.data(), a, b, rotation, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), translation, tip);
      solver.solve(f.model(), f.data(), cd, ck);
      double error = 0.0;
      for (int k = 0; k < n; ++k) error = std::max(error, (solver.link(k).angular_acc - dense.segment<3>(3 * k)).norm());
      if (grounded) {
        EXPECT_GT(contacts, 0) << "seed " << seed << ": no link in the bed";
        EXPECT_GT(solver.tipClampStiffness().norm(), 0.0);
      }
      EXPECT_LT(error, 1e-9 * dense.lpNorm<Eigen::Infinity>()) << "seed " << seed << " variant " << variant;
      // The tip's d: the load's acceleration less its known part, the tip Jacobian times the solution.
      EXPECT_LT((solver.tipDelta() - base[n] * dense).norm(), 1e-9 * (base[n] * dense).norm() + 1e-12);
    }
  }
}

TEST(ImplicitRecursion, DragDampingIsTheDragsVelocityJacobian) {
  // Link k's drag (external_loads.cpp: the Gauss quadrature of the Morison force) as the state's angular
  // velocities change: omega_k moves link k's axis rate (columns omega of the damping), omega_{k-1} its base
  // end's velocity by l_{k-1} domega x u_{k-1} (columns v_base). Uniform current: the Jacobian's
  // mid-link current is then exact.
  const int n = 6, k = 3;
  const CableParams p = stiffCable(n, false, true);
  ChainDynamics f(p);
  Eigen::VectorXd q, qd, x(f.stateSize());
  randomState(n, 5, q, qd);
  f.stateFromPaper(q, qd, x);
  const EndInputs ends;
  StiffArticulatedBody solver(n);
  f.computeLoads(x, ends);
  solver.linearize(f.model(), f.data(), ends);
  const StiffLinkTerms& t = solver.link(k);
  const Eigen::Vector3d u = f.data().links.get(&LinkBlock::u, k), prev = f.data().links.get(&LinkBlock::u, k - 1);
  const double l_prev = f.deployed().get(&LinkConstants::length, k - 1), eps = 1e-6;
  // The wrench on link k about its base end: torque u x moment, force.
  const auto wrench = [&](const Eigen::VectorXd& state) {
    f.computeLoads(state, ends);
    Eigen::Matrix<double, 6, 1> out;
    out << u.cross(f.data().links.get(&LinkBlock::moment, k)), f.data().links.get(&LinkBlock::force, k);
    return out;
  };
  double scale = 0.0, error = 0.0;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(j);
    for (int which : {k, k - 1}) {
      Eigen::VectorXd plus = x, minus = x;
      plus.segment<3>(StateLayout::omega(which)) += eps * e;
      minus.segment<3>(StateLayout::omega(which)) -= eps * e;
      const Eigen::Matrix<double, 6, 1> numeric = (wrench(plus) - wrench(minus)) / (2.0 * eps);
      Eigen::Matrix<double, 6, 1> predicted;
      if (which == k) {  // -(damping) (e, 0)
        predicted << -(t.drag_rr * e), -(t.drag_rv.transpose() * e);
      } else {  // -(damping) (0, dv), dv = l_{k-1} e x u_{k-1}
        const Eigen::Vector3d dv = l_prev * e.cross(prev);
        predicted << -(t.drag_rv * dv), -(t.drag_vv * dv);
      }
      scale = std::max(scale, numeric.norm());
      error = std::max(error, (numeric - predicted).norm());
    }
  }
  EXPECT_GT(scale, 1e-3);
  EXPECT_LT(error, 1e-6 * scale);  // central differences: round-off and eps^2 terms
}

TEST(ImplicitRecursion, SeabedStiffnessIsTheContactForcesRotationJacobian) {
  // The contact's stiffness blocks against central differences of the generalized forces in the links'
  // rotations, with the seabed less without it (the same cable: the difference is the contact's), at rest
  // (the damper and the friction then exert nothing) in air, on a flat bed 1 mm above the deepest contact
  // point or the load (a resting penetration: the spring is 100 weights per 2 cm). Left out of the blocks:
  // the bed's curvature (none here), the contact force's own turning with the link (s f = s k delta per
  // point against the spring's s^2 k: delta / s) and its change of the inboard links' tension (geometric,
  // l f): all proportional to the penetration, 0.6 to 1.5 % at 5 mm, so the tolerance 5e-3 at 1 mm.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const int n = 7, dof = 3 * n;
    const CableParams without = stiffCable(n, false, false);
    ChainDynamics free(without);
    Eigen::VectorXd q, qd, x(free.stateSize());
    randomState(n, seed + 20, q, qd);
    qd.setZero();
    free.stateFromPaper(q, qd, x);
    const EndInputs at_rest = endsFor(without, Eigen::Vector3d::Zero());
    free.computeLoads(x, at_rest);
    double deepest = 0.0;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d base = free.data().links.get(&LinkBlock::base_pos, k);
      const double l = free.deployed().get(&LinkConstants::length, k), uz = free.data().links.get(&LinkBlock::u, k).z();
      for (int j = 0; j < 4; ++j) deepest = std::max(deepest, base.z() + (j + 0.5) / 4.0 * l * uz);  // the contact points
    }
    deepest = std::max(deepest, free.data().tip_position.z());  // and the load's
    // The configured depth is below the base's rest position; the bed's paper z is what the points meet.
    const double offset = ChainModel(stiffCable(n, false, false, {"seabed={depth: 1.0}"})).seabedContact().bed.shallowest() - 1.0;
    const CableParams with = stiffCable(n, false, false, {"seabed={depth: " + std::to_string(deepest - offset - 0.001) + "}"});
    ChainDynamics bed(with);
    const EndInputs ends = endsFor(with, Eigen::Vector3d::Zero());
    const double eps = 1e-7;
    Eigen::MatrixXd difference(dof, dof);
    Eigen::VectorXd plus(dof), minus(dof), plus_free(dof), minus_free(dof);
    for (int j = 0; j < dof; ++j) {
      const int k = j / 3;
      Eigen::VectorXd px = x, mx = x;
      const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)), turn = eps * Eigen::Vector3d::Unit(j % 3);
      px.segment<3>(StateLayout::axis(k)) = Eigen::AngleAxisd(eps, turn.normalized()) * axis;
      mx.segment<3>(StateLayout::axis(k)) = Eigen::AngleAxisd(-eps, turn.normalized()) * axis;
      // The twist moves with the rotation as the kinematics have it (sigma' = -w.(e_z + u)/(1 + u_z)).
      const double twist = -turn.dot(Eigen::Vector3d::UnitZ() + axis) / (1.0 + axis.z());
      px(StateLayout::twist(k)) += twist;
      mx(StateLayout::twist(k)) -= twist;
      bed.generalizedForces(px, ends, false, plus);
      bed.generalizedForces(mx, ends, false, minus);
      free.generalizedForces(px, ends, false, plus_free);
      free.generalizedForces(mx, ends, false, minus_free);
      difference.col(j) = -((plus - minus) - (plus_free - minus_free)) / (2.0 * eps);
    }
    bed.computeLoads(x, ends);
    StiffArticulatedBody solver(n);
    solver.linearize(bed.model(), bed.data(), ends);
    // The blocks mapped through the rotations: link k's base end moves by sum_{j<k} l_j dtheta_j x u_j.
    Eigen::MatrixXd assembled = Eigen::MatrixXd::Zero(dof, dof), base = Eigen::MatrixXd::Zero(3, dof);
    int contacts = 0;
    for (int k = 0; k < n; ++k) {
      const StiffLinkTerms& t = solver.link(k);
      Eigen::MatrixXd spatial = Eigen::MatrixXd::Zero(6, dof);
      spatial.block<3, 3>(0, 3 * k).setIdentity();
      spatial.bottomRows(3) = base;
      Eigen::Matrix<double, 6, 6> contact;
      contact << solver.contact(k).rr, solver.contact(k).rv, solver.contact(k).rv.transpose(), solver.contact(k).vv;
      assembled += spatial.transpose() * contact * spatial;
      contacts += t.in_contact ? 1 : 0;
      base.block<3, 3>(0, 3 * k) += -bed.deployed().get(&LinkConstants::length, k) * skew(t.axis);
    }
    assembled += base.transpose() * solver.loadContactStiffness() * base;  // base: the tip's Jacobian now
    contacts += solver.loadContactStiffness().norm() > 0.0 ? 1 : 0;
    const double error = (assembled - difference).norm() / assembled.norm();
    std::cout << "seed " << seed << ": " << contacts << " links (or the load) in the bed, |K_blocks - K_fd| / |K_blocks| = " << error
              << "\n";
    EXPECT_GT(contacts, 0);
    EXPECT_LT(error, 5e-3);
  }
}

TEST(ImplicitRecursion, GeometricStiffnessIsTheHangingChainsPotentialHessian) {
  // A chain hanging straight down at rest in air, unequal links, a 4 kg load at its free tip. Turning link
  // k alone by a small angle a about its base end raises its own weight's centre by l_k (1 - cos a) / 2 and
  // lifts everything outboard by l_k (1 - cos a): the potential's second derivative is
  //   d2V/da2 = l_k (W_outboard,k + w' l_k / 2) g-weighted,
  // the mean tension along the link times its length. That is the geometric stiffness the implicit step
  // puts across link k, from the external loads (linearize) and from the tensions of a solve
  // (use_last_tension): the issue-28 mutation check's +1 % on it passed every test before this one.
  const int n = 6;
  const CableParams p = stiffCable(n, false, false);
  ChainDynamics f(p);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * n), qd = Eigen::VectorXd::Zero(3 * n), x(f.stateSize());
  f.stateFromPaper(q, qd, x);
  EndInputs ends;
  f.computeLoads(x, ends);
  StiffArticulatedBody solver(n);
  const double g = 9.81, w = 1.5 * g, load = 4.0 * g;  // stiffCable: 1.5 kg/m, a 4 kg load [N/m, N]
  const auto expected = [&](int k) {
    double outboard = load;
    for (int j = k + 1; j < n; ++j) outboard += w * p.link_lengths[j];
    return p.link_lengths[k] * (outboard + 0.5 * w * p.link_lengths[k]);
  };
  solver.linearize(f.model(), f.data(), ends);
  double worst_loads = 0.0;
  for (int k = 0; k < n; ++k) worst_loads = std::max(worst_loads, std::abs(solver.link(k).geometric / expected(k) - 1.0));
  // At rest the solve's tensions are the static ones.
  solver.clearExtra();
  solver.solve(f.model(), f.data(), 0.0, 0.0);
  solver.linearize(f.model(), f.data(), ends, true);
  double worst_tensions = 0.0;
  for (int k = 0; k < n; ++k) worst_tensions = std::max(worst_tensions, std::abs(solver.link(k).geometric / expected(k) - 1.0));
  std::cout << "[ geometric ] largest relative error: " << worst_loads << " from the loads, " << worst_tensions
            << " from a solve's tensions\n";
  // Measured: round-off (about 1e-15). Bound 1e-12: a 1 % error in either is 1e-2.
  EXPECT_LT(worst_loads, 1e-12);
  EXPECT_LT(worst_tensions, 1e-12);
}
