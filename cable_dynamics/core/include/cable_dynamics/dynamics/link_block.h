#pragma once
/// \file
/// \brief Per-link quantities stored eight links to a block: a structure of arrays inside each block.
///
/// The loops that treat every link alike (kinematics, drag, each link's own terms of the recursion,
/// energies) run over the eight lanes of a block, and the compiler turns them into vector instructions
/// that work on four or eight links at once. The serial loops of the recursion find all of one link's
/// values from one pointer. Lanes past the last link hold a massless link of zero length, which keeps
/// every lane finite and adds nothing to a sum.

#include <vector>

#include <Eigen/Core>

namespace cable_dynamics {

constexpr int kBlockLanes = 8;

/// Before a loop over a block's lanes that reads a LinkConstants block and writes a LinkBlock: the two
/// are separate objects (the model's and the data's), which the compiler cannot prove apart, so without
/// it GCC leaves such loops scalar (measured: 1.5x slower steps). The lanes of one loop never depend on
/// each other.
#if defined(__GNUC__) && !defined(__clang__)
#define CABLE_LANE_LOOP _Pragma("GCC ivdep")
#else
#define CABLE_LANE_LOOP
#endif

/// A 3-vector of three plain doubles, for the lane loops: Eigen's fixed-size vectors use their own
/// two-wide packets, which keep the compiler from vectorizing across links.
struct Vec3 {
  double x, y, z;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 toVec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline Eigen::Vector3d toEigen(const Vec3& v) { return {v.x, v.y, v.z}; }

/// One 3-vector quantity of the eight links of a block.
struct Lanes3 {
  double x[kBlockLanes], y[kBlockLanes], z[kBlockLanes];
  Vec3 operator[](int i) const { return {x[i], y[i], z[i]}; }
  void set(int i, const Vec3& v) {
    x[i] = v.x;
    y[i] = v.y;
    z[i] = v.z;
  }
};

/// Symmetric 3x3 matrix [xx xy xz; xy yy yz; xz yz zz], exactly symmetric by construction (the
/// recursion amplifies an antisymmetric round-off part link by link, a symmetric one not).
struct Symmetric3 {
  double xx, xy, xz, yy, yz, zz;
  static Symmetric3 scaledIdentity(double s) { return {s, 0.0, 0.0, s, 0.0, s}; }
  Vec3 operator*(const Vec3& v) const {
    return {xx * v.x + xy * v.y + xz * v.z, xy * v.x + yy * v.y + yz * v.z, xz * v.x + yz * v.y + zz * v.z};
  }
};

/// One symmetric 3x3 quantity of the eight links of a block.
struct LanesSymmetric3 {
  double xx[kBlockLanes], xy[kBlockLanes], xz[kBlockLanes], yy[kBlockLanes], yz[kBlockLanes], zz[kBlockLanes];
  Symmetric3 operator[](int i) const { return {xx[i], xy[i], xz[i], yy[i], yz[i], zz[i]}; }
  void set(int i, const Symmetric3& m) {
    xx[i] = m.xx;
    xy[i] = m.xy;
    xz[i] = m.xz;
    yy[i] = m.yy;
    yz[i] = m.yz;
    zz[i] = m.zz;
  }
};

/// Eight links' constants (SI units), set once by ChainModel and read by every pass. Lanes past the
/// last link: zero length and mass (inverse_polar 0), so they stay finite and add nothing. A link's
/// attachments (point masses at distances s_p from its base end, docs/MODEL.md section 9) are folded into
/// its moments: "inertia" below is mass plus added mass, "structure" mass alone.
struct alignas(64) LinkConstants {
  double length[kBlockLanes];           ///< l [m]
  double mass_per_length[kBlockLanes];  ///< m' [kg/m]
  double added[kBlockLanes];            ///< m_a', normal added mass per length [kg/m]
  double across[kBlockLanes];           ///< m' + m_a' [kg/m]
  double weight[kBlockLanes];           ///< submerged weight, attachments included [N]
  double weight_moment[kBlockLanes];    ///< its first moment about the base end, along the axis [N m]
  double translational[kBlockLanes];    ///< l (m' + m_a') + sum (m_p + m_pa), isotropic inertia [kg]
  double half_moment[kBlockLanes];      ///< l^2/2 (m' + m_a') + sum (m_p + m_pa) s_p [kg m]
  double third_moment[kBlockLanes];     ///< l^3/3 (m' + m_a') + sum (m_p + m_pa) s_p^2 [kg m^2]
  double own_transverse[kBlockLanes];   ///< third_moment + thickness inertia, about the base end [kg m^2]
  double thick_transverse[kBlockLanes]; ///< thickness part of the transverse inertia, m r^2/4 [kg m^2]
  double polar[kBlockLanes];            ///< I_P [kg m^2]
  double inverse_polar[kBlockLanes];    ///< 1/I_P, 0 in the padding lanes [1/(kg m^2)]
  double structure0[kBlockLanes];       ///< m' l + sum m_p, the mass (kinetic energy) [kg]
  double structure1[kBlockLanes];       ///< m' l^2/2 + sum m_p s_p [kg m]
  double structure2[kBlockLanes];       ///< m' l^3/3 + sum m_p s_p^2 [kg m^2]
  double point_added0[kBlockLanes];     ///< sum m_pa, the attachments' isotropic added mass [kg]
  double point_added1[kBlockLanes];     ///< sum m_pa s_p [kg m]
  double point_added2[kBlockLanes];     ///< sum m_pa s_p^2 [kg m^2]
  double drag_normal[kBlockLanes];      ///< 1/2 rho C_n d, times |v_n| v_n per length [kg/m^2]
  double drag_tangential[kBlockLanes];  ///< 1/2 rho C_t pi d, times |v_t| v_t per length [kg/m^2]
  double axial_stiffness[kBlockLanes];  ///< EA / l, the stretch's spring [N/m] (0: rigid links)
  double axial_damping[kBlockLanes];    ///< c_a / l, its damper on the stretch rate [N s/m]
  double far_mass[kBlockLanes];         ///< m/2 carried at the far end beyond the stretch (0: rigid) [kg]
  double far_weight[kBlockLanes];       ///< its submerged weight, + down [N]
  double far_tangential[kBlockLanes];   ///< the far half's skin friction, drag_tangential l / 2 with the body's
                                        ///< drag_tangential then halved (0: no far-end point) [kg/m]
};

/// Eight links' state-derived quantities and the recursion's intermediate results, rewritten by every
/// evaluation (SI units; what each means: docs/MODEL.md section 4). Part of ChainData.
struct alignas(64) LinkBlock {
  // Kinematics (kinematics.cpp).
  Lanes3 u;            ///< unit axis
  Lanes3 omega;        ///< angular velocity [rad/s]
  Lanes3 axis_rate;    ///< u' = omega x u [1/s]
  Lanes3 beta;         ///< omega x u': u'' at zero angular acceleration [1/s^2]
  Lanes3 base_pos;     ///< base end [m]
  Lanes3 base_vel;     ///< [m/s]
  Lanes3 known_acc;    ///< a0: base-end acceleration at zero angular accelerations [m/s^2]
  double twist_rate[kBlockLanes];  ///< sigma' [rad/s]
  // Axial elasticity (docs/MODEL.md section 12): the link's far end is l + s from its base, along u.
  // All zero with rigid links.
  double stretch[kBlockLanes];       ///< s [m]
  double stretch_rate[kBlockLanes];  ///< s' [m/s]
  double damped_rate[kBlockLanes];   ///< the rate its damper reads, AxialSpring::dampedRate [m/s]
  double axial_tension[kBlockLanes]; ///< the stretch's spring and damper, tension only [N]
  double axial_loss[kBlockLanes];    ///< power its damper takes out [W]
  double far_drag[kBlockLanes];      ///< the far half's skin friction on the far-end point, along u at the
                                     ///< point's own velocity (+ outwards; external_loads.cpp) [N]
  // External loads (external_loads.cpp, joint_torques.cpp).
  Lanes3 force;        ///< total external force on the link [N]
  Lanes3 moment;       ///< its first moment about the base end [N m]
  Lanes3 torque;       ///< joint springs and dampers on the link [N m]
  double drag_power[kBlockLanes];  ///< power of the drag on the link [W]
  // The recursion, each link on its own (articulated_body.cpp, linkTermsPass).
  Lanes3 e1, e2;              ///< basis of the plane normal to u, e1 x e2 = u
  LanesSymmetric3 own_mass;   ///< l A, the link's translational inertia [kg]
  Lanes3 own_force;           ///< A (l a0 + l^2/2 beta) - F [N]
  Lanes3 own_moment;          ///< (m' + m_a') (l^2/2 a0 + l^3/3 beta) - first moment of F [N m]
  double bias_torque1[kBlockLanes], bias_torque2[kBlockLanes];  ///< gyroscopic minus joint torque on e1, e2 [N m]
  double spin_acc[kBlockLanes];             ///< angular acceleration about u [rad/s^2]
  Lanes3 far_bias;  ///< the far-end point's m_f a0_far - f_far, a0_far its known acceleration [N]
  // The recursion's backward pass.
  Lanes3 x1, x2;              ///< transverse accelerations y = y_g - X^T a_k [1/m]
  double y1[kBlockLanes], y2[kBlockLanes];  ///< y_g [rad/s^2]
  LanesSymmetric3 mass;       ///< M_k, effective mass of the outboard part at joint k [kg] (when all
                              ///< joint forces are asked for)
  Lanes3 bias;                ///< F_k: force on the outboard part J_k = M_k d_k + F_k [N] (the same)
  // The recursion's forward pass.
  Lanes3 delta_acc;           ///< d_k, base-end acceleration less the known one [m/s^2]
  // The stretch at the far end (axial elasticity): s'' = -stretch_bias - stretch_gain . d_q, with d_q
  // the far end's acceleration (less its known part) at s'' = 0.
  Lanes3 stretch_gain;                  ///< M u / (u^T M u) of the outboard part [-]
  double stretch_bias[kBlockLanes];     ///< (T + u . F) / (u^T M u) [m/s^2]
  double stretch_acc[kBlockLanes];      ///< s'' [m/s^2]
  Lanes3 omega_rate;          ///< angular acceleration [rad/s^2]
};

/// The variable blocks of a chain of n links, with per-link access for the code that goes link by link.
class LinkBlocks {
 public:
  explicit LinkBlocks(int links = 0)
      : blocks_((links + kBlockLanes - 1) / kBlockLanes) {}

  int blocks() const { return static_cast<int>(blocks_.size()); }
  LinkBlock& block(int b) { return blocks_[b]; }
  const LinkBlock& block(int b) const { return blocks_[b]; }
  LinkBlock& of(int k) { return blocks_[k / kBlockLanes]; }
  const LinkBlock& of(int k) const { return blocks_[k / kBlockLanes]; }
  static int lane(int k) { return k % kBlockLanes; }

  /// 3-vector `field` of link k, e.g. get(&LinkBlock::u, k).
  Eigen::Vector3d get(Lanes3 LinkBlock::*field, int k) const { return toEigen((of(k).*field)[lane(k)]); }
  void set(Lanes3 LinkBlock::*field, int k, const Eigen::Vector3d& v) { (of(k).*field).set(lane(k), toVec3(v)); }
  /// Scalar `field` of link k, e.g. get(&LinkBlock::twist_rate, k).
  double get(double (LinkBlock::*field)[kBlockLanes], int k) const { return (of(k).*field)[lane(k)]; }

 private:
  std::vector<LinkBlock> blocks_;  // C++17's allocator honours the 64-byte alignment
};

}  // namespace cable_dynamics
