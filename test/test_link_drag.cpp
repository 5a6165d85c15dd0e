// The uniform-current shortcut of the link drag (one square root per Gauss point, eight links of a
// block at once) against the point-by-point Morison quadrature, and the quadrature against a fine
// midpoint rule of the same integrand (an integration written here independently of fluid.cpp's).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/fluid.h"

namespace cd = cable_dynamics;

namespace {

cd::FluidParams water(int points) {
  cd::FluidParams fluid;
  fluid.density = 1025.0;       // [kg/m^3]
  fluid.drag_normal = 1.2;      // [-]
  fluid.drag_tangential = 0.01; // [-]
  fluid.drag_points = points;
  fluid.current = Eigen::Vector3d(0.7, -0.2, 0.1);  // [m/s], world frame
  return fluid;
}

struct LinkMotion {
  Eigen::Vector3d base, velocity, axis, axis_rate;
};

LinkMotion randomMotion(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  LinkMotion m;
  m.base = Eigen::Vector3d(normal(rng), normal(rng), 5.0 + normal(rng));
  m.velocity = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  m.axis = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
  const Eigen::Vector3d omega(normal(rng), normal(rng), normal(rng));
  m.axis_rate = omega.cross(m.axis);
  return m;
}

/// The drag addUniform() adds to the eight links of a block with the given motions and lengths [m]
/// (a zero length is what a padding lane holds).
struct BlockDrag {
  Eigen::Vector3d force[cd::kBlockLanes], moment[cd::kBlockLanes];
  double power[cd::kBlockLanes];
};
BlockDrag uniformDrag(const cd::LinkDrag& drag, const Eigen::Vector3d& current, const LinkMotion* motions,
                      const double* lengths, const cd::DragCoefficients* coefficients) {
  cd::LinkConstants constants{};
  cd::LinkBlock block{};
  for (int i = 0; i < cd::kBlockLanes; ++i) {
    constants.length[i] = lengths[i];
    constants.drag_normal[i] = coefficients[i].normal;
    constants.drag_tangential[i] = coefficients[i].tangential;
    block.u.set(i, cd::toVec3(motions[i].axis));
    block.base_vel.set(i, cd::toVec3(motions[i].velocity));
    block.axis_rate.set(i, cd::toVec3(motions[i].axis_rate));
    block.base_pos.set(i, cd::toVec3(motions[i].base));
  }
  drag.addUniform(cd::toVec3(current), constants, block);
  BlockDrag out;
  for (int i = 0; i < cd::kBlockLanes; ++i) {
    out.force[i] = cd::toEigen(block.force[i]);
    out.moment[i] = cd::toEigen(block.moment[i]);
    out.power[i] = block.drag_power[i];
  }
  return out;
}

}  // namespace

TEST(LinkDrag, UniformShortcutEqualsPointwiseQuadrature) {
  // The shortcut rewrites the same Gauss sum; only round-off may differ (1e-12 of the force scale).
  std::mt19937 rng(7);
  for (int points = 1; points <= 8; ++points) {
    const cd::FluidParams fluid = water(points);
    const cd::LinkDrag drag(fluid);
    const cd::CurrentField current(fluid);
    ASSERT_TRUE(current.uniform());
    for (int trial = 0; trial < 10; ++trial) {
      LinkMotion motions[cd::kBlockLanes];
      double lengths[cd::kBlockLanes];
      cd::DragCoefficients coefficients[cd::kBlockLanes];
      for (int i = 0; i < cd::kBlockLanes; ++i) {
        motions[i] = randomMotion(rng);
        lengths[i] = 0.5 + 0.1 * (trial * cd::kBlockLanes + i);  // [m]
        // Each lane its own section: diameter and coefficients differ from lane to lane.
        coefficients[i] = cd::LinkDrag::coefficients(fluid.density, 0.01 + 0.01 * i, fluid.drag_normal * (1.0 + 0.2 * i),
                                                     fluid.drag_tangential * (1.0 + 0.3 * i));
      }
      lengths[cd::kBlockLanes - 1] = 0.0;  // as in a padding lane: no drag at all
      const BlockDrag fast = uniformDrag(drag, current.uniformValue(), motions, lengths, coefficients);
      for (int i = 0; i < cd::kBlockLanes; ++i) {
        const LinkMotion& m = motions[i];
        const double l = lengths[i];
        Eigen::Vector3d f_slow, m_slow;
        drag.pointwise(current, l, coefficients[i], m.base, m.velocity, m.axis, m.axis_rate, f_slow, m_slow);
        const double scale = f_slow.norm() + 1e-3;
        EXPECT_LT((fast.force[i] - f_slow).norm(), 1e-12 * scale) << "points " << points << " lane " << i;
        EXPECT_LT((fast.moment[i] - m_slow).norm(), 1e-12 * scale * (l + 1e-3)) << "points " << points << " lane " << i;
        const double power = f_slow.dot(m.velocity) + m_slow.dot(m.axis_rate);  // [W]
        EXPECT_NEAR(fast.power[i], power, 1e-12 * scale * (m.velocity.norm() + l * m.axis_rate.norm()) + 1e-15);
      }
      EXPECT_EQ(fast.force[cd::kBlockLanes - 1].norm(), 0.0);
      EXPECT_EQ(fast.moment[cd::kBlockLanes - 1].norm(), 0.0);
    }
  }
}

TEST(LinkDrag, GaussQuadratureMatchesFineMidpointRule) {
  // 8 Gauss points against 20000 midpoint cells of 1/2 rho d (C_n |v_n| v_n + C_t pi |v_t| v_t),
  // v = current - (v0 + s u'). The integrand is smooth here (the normal relative speed stays away from
  // zero), so both converge; 1e-6 relative is far above either's error.
  const cd::FluidParams fluid = water(8);
  const double d = 0.025, l = 2.0;
  const cd::LinkDrag drag(fluid);
  const cd::CurrentField current(fluid);
  const Eigen::Vector3d c = current.uniformValue();
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.1, 0.9).normalized();
  const Eigen::Vector3d velocity(-0.4, 0.2, 0.0), axis_rate = Eigen::Vector3d(0.0, 0.5, 0.2).cross(axis);
  LinkMotion motions[cd::kBlockLanes];
  double lengths[cd::kBlockLanes];
  cd::DragCoefficients coefficients[cd::kBlockLanes];
  for (int i = 0; i < cd::kBlockLanes; ++i) {
    motions[i] = {Eigen::Vector3d(0.0, 0.0, 5.0), velocity, axis, axis_rate};
    lengths[i] = l;
    coefficients[i] = cd::LinkDrag::coefficients(fluid.density, d, fluid.drag_normal, fluid.drag_tangential);
  }
  const BlockDrag block = uniformDrag(drag, c, motions, lengths, coefficients);
  const Eigen::Vector3d force = block.force[0], moment = block.moment[0];
  Eigen::Vector3d f_ref = Eigen::Vector3d::Zero(), m_ref = Eigen::Vector3d::Zero();
  const int cells = 20000;
  for (int i = 0; i < cells; ++i) {
    const double s = (i + 0.5) * l / cells, ds = l / cells;
    const Eigen::Vector3d v = c - (velocity + s * axis_rate);
    const Eigen::Vector3d vt = v.dot(axis) * axis, vn = v - vt;
    const Eigen::Vector3d per_length =
        0.5 * fluid.density * d * (fluid.drag_normal * vn.norm() * vn + fluid.drag_tangential * M_PI * vt.norm() * vt);
    f_ref += ds * per_length;
    m_ref += (s * ds) * per_length;
  }
  EXPECT_LT((force - f_ref).norm(), 1e-6 * f_ref.norm());
  EXPECT_LT((moment - m_ref).norm(), 1e-6 * m_ref.norm());
}
