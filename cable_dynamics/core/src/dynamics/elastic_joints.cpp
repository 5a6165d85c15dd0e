#include "cable_dynamics/dynamics/elastic_joints.h"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/AutoDiff>

#include "cable_dynamics/dynamics/forces/fold_stop.h"
#include "cable_dynamics/dynamics/joint_geometry.h"

namespace cable_dynamics {
namespace {

// The bending-model energy of one joint is a function of four local variables,
// x = (te_{k-1}, te_k, a_k, t_k); its gradient and Hessian come from forward-mode automatic
// differentiation (exact to rounding, not finite differences), with fixed-size types: no heap.
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Ad1 = Eigen::AutoDiffScalar<Vec4>;
using Ad1Vec4 = Eigen::Matrix<Ad1, 4, 1>;
using Ad2 = Eigen::AutoDiffScalar<Ad1Vec4>;

inline double valueOf(double x) { return x; }
inline double valueOf(const Ad1& x) { return x.value(); }
inline double valueOf(const Ad2& x) { return x.value().value(); }

/// Bend angle squared and twist of joint k from x = (te_prev, te, a, t), by the geometry the dynamics
/// use (joint_geometry.h). The previous link's azimuth is taken as zero: both quantities are invariant
/// to a common rotation about the vertical.
template <typename S>
void bendTwist(const S& te_prev, const S& te, const S& a, const S& t, S& bend_squared, S& twist) {
  using std::cos;
  using std::sin;
  const S ax = S(0.0), ay = sin(te_prev), az = cos(te_prev);
  const S bx = sin(te) * sin(a), by = sin(te) * cos(a), bz = cos(te);
  const S dx = ax - bx, dy = ay - by, dz = az - bz;
  const S chord_squared = dx * dx + dy * dy + dz * dz;
  bend_squared = bendAngleSquared(chord_squared, valueOf(chord_squared));
  // Euler angles make the twist psi + phi relative to the vertical; subtracting the transport holonomy
  // leaves the twist between neighbours (sigma_k - sigma_{k-1} = a_k + t_k).
  twist = a + t - transportHolonomy(ax, ay, az, bx, by, bz);
  twist = principalTwist(twist, valueOf(twist));  // as the dynamics' jointGeometry
}

/// The joint's springs, and its fold stop (forces/fold_stop.h; inactive for joint 1, at the clamp).
template <typename S>
S jointEnergy(const S& te_prev, const S& te, const S& a, const S& t, double k_bend, double k_twist, const FoldStop& stop) {
  using std::sqrt;
  S bend_squared, twist;
  bendTwist(te_prev, te, a, t, bend_squared, twist);
  S energy = 0.5 * k_bend * bend_squared + 0.5 * k_twist * twist * twist;
  const double bend = std::sqrt(std::max(0.0, valueOf(bend_squared)));
  if (stop.engaged(bend)) energy += stop.energyOf(S(sqrt(bend_squared)), bend);
  return energy;
}

/// Global indices of the local variables of joint k; -1 where the variable is the fixed base.
inline void localIndices(int k, int idx[4]) {
  idx[0] = k > 0 ? 3 * (k - 1) : -1;
  idx[1] = 3 * k;
  idx[2] = 3 * k + 1;
  idx[3] = 3 * k + 2;
}

/// Local variable i of joint k: for joint 1 the "previous link" is the base clamp (elevation te_c), and
/// link 1's azimuth is taken relative to the clamp's psi_c (so that the twist is a + t - psi_c - Omega:
/// the clamp frame's sigma is psi_c, as in LinkProperties::clamp_twist).
inline double localValue(const Eigen::VectorXd& q, int k, int i, double clamp_elevation, double clamp_azimuth) {
  if (k == 0 && i == 0) return clamp_elevation;
  const double value = q(i == 0 ? 3 * (k - 1) : 3 * k + i - 1);
  return k == 0 && i == 2 ? value - clamp_azimuth : value;
}

}  // namespace

double ElasticJoints::local(const Eigen::VectorXd& q, int k, int i) const {
  return localValue(q, k, i, clamp_elevation_, clamp_azimuth_);
}

ElasticJoints::ElasticJoints(const LinkProperties& p)
    : n_(p.n),
      model_(p.stiffness_model),
      clamp_elevation_(std::atan2(std::hypot(p.clamp_axis.x(), p.clamp_axis.y()), p.clamp_axis.z())),
      clamp_azimuth_(p.clamp_twist) {
  k_diag_.resize(3 * n_);
  c_diag_.resize(3 * n_);
  for (int k = 0; k < n_; ++k) {
    k_diag_.segment<3>(3 * k) << p.stiffness_elevation(k), p.stiffness_azimuth(k), p.stiffness_torsion(k);
    c_diag_.segment<3>(3 * k) << p.damping_elevation(k), p.damping_azimuth(k), p.damping_torsion(k);
  }
  // The fold stops between links, as ChainModel::foldStop builds them for the dynamics.
  stops_.assign(n_, FoldStop{});
  const double tension = FoldStop::tensionOf(p);
  for (int k = 1; k < n_ && model_ == StiffnessModel::kBending; ++k) {
    stops_[k] = FoldStop::ofJoint(p, k, tension);
  }
}

double ElasticJoints::energy(const Eigen::VectorXd& q) const {
  if (model_ == StiffnessModel::kPaper) return 0.5 * q.dot(k_diag_.cwiseProduct(q));
  double v = 0.0;
  for (int k = 0; k < n_; ++k) {
    v += jointEnergy(local(q, k, 0), local(q, k, 1), local(q, k, 2), local(q, k, 3), k_diag_(3 * k), k_diag_(3 * k + 2),
                     stops_[k]);
  }
  return v;
}

void ElasticJoints::force(const Eigen::VectorXd& q, Eigen::VectorXd& out) const {
  if (model_ == StiffnessModel::kPaper) {
    out = k_diag_.cwiseProduct(q);
    return;
  }
  out.setZero();
  int idx[4];
  for (int k = 0; k < n_; ++k) {
    localIndices(k, idx);
    Ad1 x[4];
    for (int i = 0; i < 4; ++i) x[i] = Ad1(local(q, k, i), 4, i);
    const Ad1 v = jointEnergy(x[0], x[1], x[2], x[3], k_diag_(3 * k), k_diag_(3 * k + 2), stops_[k]);
    for (int i = 0; i < 4; ++i) {
      if (idx[i] >= 0) out(idx[i]) += v.derivatives()(i);
    }
  }
}

void ElasticJoints::stiffness(const Eigen::VectorXd& q, Eigen::MatrixXd& out) const {
  out.setZero();
  if (model_ == StiffnessModel::kPaper) {
    out.diagonal() = k_diag_;
    return;
  }
  int idx[4];
  for (int k = 0; k < n_; ++k) {
    localIndices(k, idx);
    Ad2 x[4];
    for (int i = 0; i < 4; ++i) {
      // Outer derivative seeds i; the value itself carries the inner seed i for the second derivative.
      Ad1Vec4 outer_seed = Ad1Vec4::Constant(Ad1(0.0, Vec4::Zero()));
      outer_seed(i) = Ad1(1.0, Vec4::Zero());
      x[i] = Ad2(Ad1(local(q, k, i), 4, i), outer_seed);
    }
    const Ad2 v = jointEnergy(x[0], x[1], x[2], x[3], k_diag_(3 * k), k_diag_(3 * k + 2), stops_[k]);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        if (idx[i] >= 0 && idx[j] >= 0) out(idx[i], idx[j]) += v.derivatives()(i).derivatives()(j);
      }
    }
  }
}

void ElasticJoints::damping(Eigen::MatrixXd& out) const {
  out.setZero();
  out.diagonal() = c_diag_;
}

void ElasticJoints::bendAndTwist(const Eigen::VectorXd& q, int k, double& bend, double& twist) const {
  double bend_squared = 0.0;
  bendTwist(local(q, k, 0), local(q, k, 1), local(q, k, 2), local(q, k, 3), bend_squared, twist);
  bend = std::sqrt(std::max(0.0, bend_squared));
}

}  // namespace cable_dynamics
