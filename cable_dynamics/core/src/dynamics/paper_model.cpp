#include "cable_dynamics/dynamics/paper_model.h"

#include <cassert>
#include <cmath>

#include "cable_dynamics/dynamics/elastic_joints.h"

namespace cable_dynamics {

PaperModelTerms paperModelAt(const LinkProperties& props, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const int dof = 3 * props.n;
  PaperModel model(props);
  const ElasticJoints joints(props);
  PaperModelTerms t;
  t.M.resize(dof, dof);
  t.K.resize(dof, dof);
  t.D.resize(dof, dof);
  t.h.resize(dof);
  t.G.resize(dof);
  t.elastic.resize(dof);
  model.compute(q, qd, t.M, t.h, t.G);
  joints.stiffness(q, t.K);
  joints.force(q, t.elastic);
  joints.damping(t.D);
  t.kinetic_energy = 0.5 * qd.dot(t.M * qd);
  t.potential_energy = model.potentialEnergy(q);
  t.elastic_energy = joints.energy(q);
  return t;
}

Eigen::Vector3d linkAxis(double elevation, double absolute_azimuth) {
  const double st = std::sin(elevation);
  return {st * std::sin(absolute_azimuth), st * std::cos(absolute_azimuth), std::cos(elevation)};
}

PaperModel::PaperModel(const LinkProperties& properties) : n_(properties.n), props_(properties) {
  const int n = n_;
  const Eigen::VectorXd& l = props_.length;
  const Eigen::VectorXd& m = props_.mass;
  // Mass and submerged mass outboard of each link (every link beyond it plus the load) [kg].
  Eigen::VectorXd outboard(n), outboard_submerged(n);
  double sum = props_.load_mass, sum_submerged = props_.load_submerged_mass;
  for (int j = n - 1; j >= 0; --j) {
    outboard(j) = sum;
    outboard_submerged(j) = sum_submerged;
    sum += m(j);
    sum_submerged += props_.submerged_mass(j);
  }
  // Body b's CoM is sum_j lambda_bj u_j with lambda_bj = l_j (j < b), l_b/2 (j = b), 0 (j > b); the load
  // has lambda = l_j for all j. Summing m_b lambda_bi lambda_bj over the bodies gives mu_ij below.
  mu_.resize(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int outer = std::max(i, j);
      mu_(i, j) = i == j ? l(i) * l(i) * (m(i) / 4.0 + outboard(i)) : l(i) * l(j) * (m(outer) / 2.0 + outboard(outer));
    }
  }
  gamma_ = l.cwiseProduct(props_.submerged_mass / 2.0 + outboard_submerged);

  psi_.resize(n);
  psi_rate_.resize(n);
  phi_rate_.resize(n);
  u_.resize(3, n);
  e_.resize(3, n);
  w_.resize(3, n);
  accel_velocity_.resize(3, n);
  block_te_te_.resize(n, n);
  block_te_psi_.resize(n, n);
  block_psi_psi_.resize(n, n);
  h_te_.resize(n);
  h_psi_.resize(n);
  h_phi_.resize(n);
  polar_cos_suffix_.resize(n);
  polar_suffix_.resize(n);
}

void PaperModel::compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::MatrixXd& M,
                         Eigen::VectorXd& h, Eigen::VectorXd& G) {
  const int n = n_;
  assert(q.size() == 3 * n && qd.size() == 3 * n);
  assert(M.rows() == 3 * n && M.cols() == 3 * n && h.size() == 3 * n && G.size() == 3 * n);
  const Eigen::VectorXd& it = props_.inertia_transverse;
  const Eigen::VectorXd& ip = props_.inertia_polar;

  // Absolute angles psi_k = sum a_i, and their rates; per-link unit vectors.
  double psi = 0.0, psi_rate = 0.0, phi_rate = 0.0;
  for (int k = 0; k < n; ++k) {
    psi += q(3 * k + 1);
    psi_rate += qd(3 * k + 1);
    phi_rate += qd(3 * k + 2);
    psi_(k) = psi;
    psi_rate_(k) = psi_rate;
    phi_rate_(k) = phi_rate;
    const double te = q(3 * k), te_rate = qd(3 * k);
    const double ct = std::cos(te), st = std::sin(te), cp = std::cos(psi), sp = std::sin(psi);
    u_.col(k) << st * sp, st * cp, ct;          // link axis
    e_.col(k) << ct * sp, ct * cp, -st;         // d u / d te
    w_.col(k) << st * cp, -st * sp, 0.0;        // d u / d psi
    // Velocity-dependent part of u'': -u te'^2 + 2 cos(te) n te' psi' - sin(te) m psi'^2,
    // with n = (cos psi, -sin psi, 0) and m = (sin psi, cos psi, 0).
    const Eigen::Vector3d nvec(cp, -sp, 0.0), mvec(sp, cp, 0.0);
    accel_velocity_.col(k) = -u_.col(k) * te_rate * te_rate + 2.0 * ct * te_rate * psi_rate * nvec -
                             st * psi_rate * psi_rate * mvec;
  }

  // Blocks in the absolute angles (te, psi, phi): translation through mu, rotation on the diagonal.
  for (int i = 0; i < n; ++i) {
    double h_te = 0.0, h_psi = 0.0;
    for (int j = 0; j < n; ++j) {
      const double mu = mu_(i, j);
      block_te_te_(i, j) = mu * e_.col(i).dot(e_.col(j));
      block_te_psi_(i, j) = mu * e_.col(i).dot(w_.col(j));
      block_psi_psi_(i, j) = mu * w_.col(i).dot(w_.col(j));
      h_te += mu * e_.col(i).dot(accel_velocity_.col(j));
      h_psi += mu * w_.col(i).dot(accel_velocity_.col(j));
    }
    // Rotation of an axisymmetric link: T = 1/2 I_T (te'^2 + sin^2 te psi'^2) + 1/2 I_P (phi' + cos te psi')^2.
    const double te = q(3 * i), te_rate = qd(3 * i);
    const double ct = std::cos(te), st = std::sin(te);
    const double pr = psi_rate_(i), spin = phi_rate_(i) + ct * pr;
    block_te_te_(i, i) += it(i);
    block_psi_psi_(i, i) += it(i) * st * st + ip(i) * ct * ct;
    h_te_(i) = h_te - it(i) * st * ct * pr * pr + ip(i) * spin * st * pr;
    h_psi_(i) = h_psi + 2.0 * it(i) * st * ct * te_rate * pr - ip(i) * ct * st * te_rate * pr -
                ip(i) * spin * st * te_rate;
    h_phi_(i) = -ip(i) * st * te_rate * pr;
  }

  // Map to the paper's relative coordinates: psi = L a, phi = L t with L lower-triangular ones, so
  // M_q = T^T M_abs T and h_q = T^T h_abs become suffix sums over the outboard links.
  for (int i = 0; i < n; ++i) {
    for (int j = n - 2; j >= 0; --j) block_te_psi_(i, j) += block_te_psi_(i, j + 1);
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int j = n - 1; j >= 0; --j) {
      double& s = block_psi_psi_(i, j);
      if (i + 1 < n) s += block_psi_psi_(i + 1, j);
      if (j + 1 < n) s += block_psi_psi_(i, j + 1);
      if (i + 1 < n && j + 1 < n) s -= block_psi_psi_(i + 1, j + 1);
    }
  }
  // Polar-inertia suffix sums: sum_{i >= k} I_P,i cos te_i and sum_{i >= k} I_P,i, and h suffix sums.
  double polar_cos = 0.0, polar = 0.0, h_psi_sum = 0.0, h_phi_sum = 0.0;
  for (int k = n - 1; k >= 0; --k) {
    polar_cos += ip(k) * std::cos(q(3 * k));
    polar += ip(k);
    h_psi_sum += h_psi_(k);
    h_phi_sum += h_phi_(k);
    polar_cos_suffix_(k) = polar_cos;
    polar_suffix_(k) = polar;
    h(3 * k) = h_te_(k);
    h(3 * k + 1) = h_psi_sum;
    h(3 * k + 2) = h_phi_sum;
    G(3 * k) = props_.gravity * gamma_(k) * std::sin(q(3 * k));
    G(3 * k + 1) = 0.0;
    G(3 * k + 2) = 0.0;
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int outer = std::max(i, j);
      M(3 * i, 3 * j) = block_te_te_(i, j);
      M(3 * i, 3 * j + 1) = block_te_psi_(i, j);
      M(3 * j + 1, 3 * i) = block_te_psi_(i, j);
      M(3 * i, 3 * j + 2) = 0.0;
      M(3 * j + 2, 3 * i) = 0.0;
      M(3 * i + 1, 3 * j + 1) = block_psi_psi_(i, j);
      // (a_i, t_j) and (t_i, t_j): polar inertia of every link outboard of both joints.
      M(3 * i + 1, 3 * j + 2) = polar_cos_suffix_(outer);
      M(3 * i + 2, 3 * j + 1) = polar_cos_suffix_(outer);
      M(3 * i + 2, 3 * j + 2) = polar_suffix_(outer);
    }
  }
}

double PaperModel::potentialEnergy(const Eigen::VectorXd& q) const {
  // V = -g sum_b ms_b z_b with z down; z_b = sum_j lambda_bj cos te_j, so V = -g sum_j gamma_j cos te_j.
  double v = 0.0;
  for (int k = 0; k < n_; ++k) v -= props_.gravity * gamma_(k) * std::cos(q(3 * k));
  return v;
}

void PaperModel::linkEnds(const Eigen::VectorXd& q, Eigen::Matrix3Xd& ends) const {
  assert(ends.cols() == n_ + 1);
  ends.col(0).setZero();
  double psi = 0.0;
  for (int k = 0; k < n_; ++k) {
    psi += q(3 * k + 1);
    ends.col(k + 1) = ends.col(k) + props_.length(k) * linkAxis(q(3 * k), psi);
  }
}

void PaperModel::centresOfMass(const Eigen::VectorXd& q, Eigen::Matrix3Xd& com) const {
  assert(com.cols() == n_);
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  double psi = 0.0;
  for (int k = 0; k < n_; ++k) {
    psi += q(3 * k + 1);
    const Eigen::Vector3d axis = linkAxis(q(3 * k), psi);
    com.col(k) = base + 0.5 * props_.length(k) * axis;
    base += props_.length(k) * axis;
  }
}

}  // namespace cable_dynamics
