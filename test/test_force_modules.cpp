// Each force module of dynamics/forces/ against central differences of its own value: the Jacobian the
// implicit step uses is the derivative of the force the explicit evaluation applies, where the module says
// it is exact, and its form at rest is its value at zero velocity. Central differences with step h have
// error O(h^2 f''') plus round-off O(eps f / h): h = 1e-6 of the variable's scale keeps both near 1e-9
// relative for these smooth laws; each tolerance below states the error measured.
#include <cmath>
#include <functional>
#include <iostream>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "cable_dynamics/dynamics/forces/contact.h"
#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/point_drag.h"
#include "cable_dynamics/dynamics/forces/tip_clamp.h"
#include "cable_dynamics/dynamics/fluid.h"

using namespace cable_dynamics;

namespace {

/// -d f / d y by central differences (3 x 3), y in R^3, step h.
Eigen::Matrix3d minusJacobian(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f, const Eigen::Vector3d& y,
                              double h) {
  Eigen::Matrix3d j;
  for (int c = 0; c < 3; ++c) {
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(c);
    j.col(c) = -(f(y + e) - f(y - e)) / (2.0 * h);
  }
  return j;
}

/// The largest entry of a - b relative to the largest of b.
double relative(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

}  // namespace

TEST(ForceModules, CouplingJacobianIsItsValuesDerivative) {
  const LoadCoupling coupling{2.0e4, 2.0e3};
  const Eigen::Vector3d x(1.0, -2.0, 30.0), v(0.3, 0.1, -0.2), xt(1.5, -1.0, 29.0), vt(0.0, 0.2, 0.1);
  const Eigen::Matrix3d dx = minusJacobian([&](const Eigen::Vector3d& y) { return coupling.force(y, v, xt, vt); }, x, 1e-5);
  const Eigen::Matrix3d dv = minusJacobian([&](const Eigen::Vector3d& y) { return coupling.force(x, y, xt, vt); }, v, 1e-6);
  const Eigen::Matrix3d k = coupling.stiffnessJacobian() * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d c = coupling.dampingJacobian() * Eigen::Matrix3d::Identity();
  std::cout << "coupling: stiffness off by " << relative(dx, k) << ", damping by " << relative(dv, c) << std::endl;
  EXPECT_LT(relative(dx, k), 1e-9);  // linear law: measured 3.3e-11 (round-off only)
  EXPECT_LT(relative(dv, c), 1e-9);  // measured 2.0e-10
  // At rest it is the value at zero velocities; its power is F.v, and the first-order shift of the power
  // matches the power at a displaced state to second order.
  EXPECT_EQ(coupling.atRest(x, xt), coupling.force(x, Eigen::Vector3d::Zero(), xt, Eigen::Vector3d::Zero()));
  const Eigen::Vector3d f = coupling.force(x, v, xt, vt);
  for (const double s : {1e-2, 5e-3}) {
    const Eigen::Vector3d ddx(0.2 * s, -0.1 * s, 0.3 * s), ddv(-0.4 * s, 0.2 * s, 0.1 * s);
    const double moved = LoadCoupling::power(coupling.force(x + ddx, v + ddv, xt, vt), v + ddv);
    const double predicted = LoadCoupling::power(f, v) + coupling.powerShift(f, v, ddx, ddv);
    // Second order in the shift: the remainder is -(k dx + c dv).dv exactly.
    EXPECT_NEAR(moved - predicted, -(coupling.stiffness * ddx + coupling.damping * ddv).dot(ddv), 1e-9 * std::abs(moved));
  }
}

TEST(ForceModules, PointDragDampingIsItsValuesDerivative) {
  const double rho = 1025.0, area = 0.4;
  const Eigen::Vector3d current(0.5, 0.1, 0.0);
  for (const Eigen::Vector3d& v : {Eigen::Vector3d(0.3, -0.2, 0.4), Eigen::Vector3d(-1.0, 0.5, 0.05)}) {
    const Eigen::Matrix3d numeric =
        minusJacobian([&](const Eigen::Vector3d& y) { return pointDrag(rho, area, y, current); }, v, 1e-6);
    const Eigen::Matrix3d analytic = pointDragDamping(rho, area, v, current);
    std::cout << "point drag at |v - c| = " << (v - current).norm() << ": damping off by " << relative(numeric, analytic)
              << std::endl;
    EXPECT_LT(relative(numeric, analytic), 2e-10);  // measured 2.9e-11
    EXPECT_DOUBLE_EQ(pointDragPower(pointDrag(rho, area, v, current), v), pointDrag(rho, area, v, current).dot(v));
  }
  EXPECT_EQ(pointDragAtRest(rho, area, current), pointDrag(rho, area, Eigen::Vector3d::Zero(), current));
}

TEST(ForceModules, ContactJacobianIsItsValuesDerivativeWhereItSaysItIsExact) {
  // A link's point on a flat bed (normal +z, into the bed), penetrating beyond the ramp (delta > rest),
  // moving into the bed (delta' > 0) without slip: there the law is smooth and the module's Jacobian
  // exact. Slipping inside the friction's viscous band at zero normal speed, the damping is exact too
  // without the normal damper (whose variation the friction's damping leaves out).
  ContactLaw law;
  law.stiffness = 5.0e4;
  law.damping = 800.0;
  law.rest = 1e-3;
  law.friction_axial = 0.3;
  law.friction_lateral = 0.6;
  law.friction_velocity = 0.01;
  const double depth = 8.0;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 0.4, 0.05).normalized();
  auto place = [&](const Eigen::Vector3d& p) {
    ContactPlace q;
    q.delta = p.z() - depth;
    q.has_along = alongTheBed(toVec3(axis), q.normal, q.along);
    return q;
  };
  auto force = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& v) {
    PointContact out;
    contactForce(law, place(p), toVec3(v), out);
    return toEigen(out.force);
  };
  const Eigen::Vector3d p(2.0, 1.0, depth + 4e-3);
  for (const Eigen::Vector3d& v : {Eigen::Vector3d(0.0, 0.0, 0.05), Eigen::Vector3d(0.003, -0.004, 0.0)}) {
    // Slipping, the friction's magnitude follows the normal force, whose damper term the module leaves
    // out of the friction's damping: exact without the damper.
    const double damper = law.damping;
    if (v.z() == 0.0) law.damping = 0.0;
    Eigen::Matrix3d stiffness, damping;
    contactJacobian(law, place(p), v, stiffness, damping);
    const Eigen::Matrix3d dx = minusJacobian([&](const Eigen::Vector3d& y) { return force(y, v); }, p, 1e-7);
    const Eigen::Matrix3d dv = minusJacobian([&](const Eigen::Vector3d& y) { return force(p, y); }, v, 1e-7);
    law.damping = damper;
    std::cout << "contact at v = " << v.transpose() << ": stiffness off by " << relative(dx, stiffness)
              << ", damping by " << relative(dv, damping) << std::endl;
    if (v.z() > 0.0) {  // no slip: both exact
      EXPECT_LT(relative(dx, stiffness), 3e-8);  // measured 6.1e-9 (h = 1e-7 m against delta = 4e-3 m)
      EXPECT_LT(relative(dv, damping), 3e-11);   // measured 2.3e-12
    } else {  // slip in the viscous band at zero normal speed: the damping is the tangent
      EXPECT_LT(relative(dv, damping), 3e-11);   // measured 6.6e-12 (the stiffness, 0.25 off, leaves the
                                                 // friction's dependence on the normal force out: documented)
    }
  }
  // Its form at rest is the value at zero velocity, and the energy's gradient is minus that force.
  PointContact still;
  contactForce(law, place(p), {0.0, 0.0, 0.0}, still);
  EXPECT_LT((toEigen(still.force) - contactForceAtRest(law, place(p))).norm(), 1e-12 * toEigen(still.force).norm());
  const double h = 1e-7;
  const double gradient = (contactEnergy(law, place(p).delta + h) - contactEnergy(law, place(p).delta - h)) / (2.0 * h);
  EXPECT_NEAR(gradient, -toEigen(still.force).z(), 1e-6 * std::abs(gradient));
  // Dissipation: what the spring does not store, >= 0, and the power of the force less the spring's.
  const Eigen::Vector3d v(0.02, -0.01, 0.03);
  PointContact moving;
  contactForce(law, place(p), toVec3(v), moving);
  const double spring_power = law.stiffness * place(p).delta * v.z();  // dV/dt = k delta delta': the spring takes it
  EXPECT_GE(moving.dissipation, 0.0);
  EXPECT_NEAR(moving.dissipation, -(toEigen(moving.force).dot(v) + spring_power), 1e-9 * moving.dissipation);
}

TEST(ForceModules, TipClampJacobianIsItsTorquesDerivativeAtSmallBends) {
  // The spring's torque on the last link, -springOnClamp(u, a), against small rotations theta of the
  // link (u -> exp([theta]x) u): the module's k (I - m m^T) is the tangent at zero bend; at a bend beta
  // the exact tangent (not symmetric away from it) differs by O(beta) k: measured 0.50 beta k at beta = 1e-3
  // and 1e-2 (the antisymmetric part of u a^T, beta / 2).
  const TipClamp clamp{1000.0, 50.0};
  const Eigen::Vector3d a = Eigen::Vector3d(0.2, 0.1, 1.0).normalized();
  for (const double beta : {1e-3, 1e-2}) {
    const Eigen::Vector3d turn_axis = a.cross(Eigen::Vector3d::UnitX()).normalized();
    const Eigen::Vector3d u = Eigen::AngleAxisd(beta, turn_axis) * a;
    auto torque = [&](const Eigen::Vector3d& theta) {
      const Eigen::Vector3d turned = theta.norm() > 0.0 ? Eigen::Vector3d(Eigen::AngleAxisd(theta.norm(), theta.normalized()) * u) : u;
      return Eigen::Vector3d(-clamp.springOnClamp(turned, a));
    };
    Eigen::Matrix3d spring, damper;
    clamp.jacobian(u, a, spring, damper);
    const Eigen::Matrix3d numeric = minusJacobian(torque, Eigen::Vector3d::Zero(), 1e-7);
    const double off = relative(numeric, spring);
    std::cout << "tip clamp at bend " << beta << ": stiffness off by " << off << " of k" << std::endl;
    EXPECT_LT(off, 1.5 * beta);
    // Its energy's gradient is minus its torque (beta: 1/2 k beta^2 grows at k beta).
    EXPECT_NEAR(clamp.energy(u, a), 0.5 * clamp.stiffness * beta * beta, 1e-12 * clamp.stiffness);
    EXPECT_NEAR(clamp.springOnClamp(u, a).norm(), clamp.stiffness * beta, 1e-9 * clamp.stiffness * beta);
  }
  // The damper: linear in the relative angular velocity, its Jacobian c (I - m m^T) exact.
  const Eigen::Vector3d u = Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()) * a;
  Eigen::Matrix3d spring, damper;
  clamp.jacobian(u, a, spring, damper);
  const Eigen::Matrix3d numeric = minusJacobian(
      [&](const Eigen::Vector3d& w) { return Eigen::Vector3d(-clamp.damperOnClamp(u, a, w, Eigen::Vector3d::Zero())); },
      Eigen::Vector3d(0.1, -0.2, 0.05), 1e-6);
  std::cout << "tip clamp damper: off by " << relative(numeric, damper) << std::endl;
  EXPECT_LT(relative(numeric, damper), 1e-10);  // linear: measured 1.7e-11
}

TEST(ForceModules, LinkDragDampingIsItsValuesDerivativeInAUniformCurrent) {
  // LinkDrag::damping against central differences of LinkDrag::pointwise (the same quadrature, point by
  // point) in the link's base velocity v and angular velocity omega (u' = omega x u): vv = -dF/dv,
  // rv = -d(u x N)/dv, rv^T = -dF/domega, rr = -d(u x N)/domega, N the first moment. Exact in a uniform
  // current (the damping takes it at the middle).
  FluidParams fluid;
  fluid.current = Eigen::Vector3d(0.6, -0.2, 0.0);
  fluid.drag_points = 5;
  const CurrentField current(fluid);
  const LinkDrag drag(fluid);
  const DragCoefficients c = LinkDrag::coefficients(1025.0, 0.05, 1.2, 0.008);
  const double l = 2.5;
  const Eigen::Vector3d base(1.0, 2.0, 5.0), u = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Eigen::Vector3d v0(0.2, 0.4, -0.1), omega0(0.05, -0.3, 0.2);
  auto loads = [&](const Eigen::Vector3d& v, const Eigen::Vector3d& omega, Eigen::Vector3d& torque) {
    Eigen::Vector3d force, moment;
    drag.pointwise(current, l, c, base, v, u, omega.cross(u), force, moment);
    torque = u.cross(moment);
    return force;
  };
  Eigen::Matrix3d vv, rv, rr, rv_t;
  for (int j = 0; j < 3; ++j) {
    const double h = 1e-6;
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
    Eigen::Vector3d tp, tm;
    const Eigen::Vector3d fp = loads(v0 + e, omega0, tp), fm = loads(v0 - e, omega0, tm);
    vv.col(j) = -(fp - fm) / (2.0 * h);
    rv.col(j) = -(tp - tm) / (2.0 * h);
    const Eigen::Vector3d gp = loads(v0, omega0 + e, tp), gm = loads(v0, omega0 - e, tm);
    rv_t.col(j) = -(gp - gm) / (2.0 * h);
    rr.col(j) = -(tp - tm) / (2.0 * h);
  }
  Eigen::Matrix3d a_rr, a_rv, a_vv;
  drag.damping(l, c, u, current.uniformValue() - v0, omega0.cross(u), a_rr, a_rv, a_vv);
  std::cout << "link drag: vv off by " << relative(vv, a_vv) << ", rv by " << relative(rv, a_rv) << ", rv^T by "
            << relative(rv_t, a_rv.transpose()) << ", rr by " << relative(rr, a_rr) << std::endl;
  EXPECT_LT(relative(vv, a_vv), 3e-10);  // measured 3.6e-11
  EXPECT_LT(relative(rv, a_rv), 3e-10);  // 4.2e-11
  EXPECT_LT(relative(rv_t, a_rv.transpose()), 3e-10);  // 2.4e-11
  EXPECT_LT(relative(rr, a_rr), 3e-10);  // 2.1e-11
}
