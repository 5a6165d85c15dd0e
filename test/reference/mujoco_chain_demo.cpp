// Standalone check of the MuJoCo chain reference (not part of the CMake build).
//   g++ -std=c++17 -O2 -I/usr/include/eigen3 test/reference/mujoco_chain.cpp
//       test/reference/mujoco_chain_demo.cpp -lmujoco -o /tmp/mujoco_chain_demo   (one line)
//   /tmp/mujoco_chain_demo [--print-mjcf]
// Exit status 0 if every check passes.
#include "mujoco_chain.h"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

using cable_reference::ChainSpec;
using cable_reference::ChainTrajectory;

namespace {

int g_failures = 0;

void check(bool ok, const char* what, double value, double tol) {
  std::printf("  [%s] %-58s %.3e (tol %.1e)\n", ok ? " OK " : "FAIL", what, value, tol);
  if (!ok) ++g_failures;
}

Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// Cylinder-like link: transverse and polar inertia about the CoM for radius r.
void addLink(ChainSpec& s, double l, double m, double r, const Eigen::Matrix3d& R, const Eigen::Vector3d& w) {
  s.length.push_back(l);
  s.mass.push_back(m);
  s.inertia_transverse.push_back(m * (3.0 * r * r + l * l) / 12.0);
  s.inertia_polar.push_back(0.5 * m * r * r);
  s.rotation.push_back(R);
  s.angular_velocity.push_back(w);
}

// Max over samples of | |end_k - end_{k-1}| - l_k |.
double lengthError(const ChainSpec& s, const ChainTrajectory& tr) {
  double e = 0.0;
  for (const auto& ends : tr.ends)
    for (std::size_t k = 0; k < s.length.size(); ++k)
      e = std::max(e, std::abs((ends[k + 1] - ends[k]).norm() - s.length[k]));
  return e;
}

// Max over links of | (end_k - end_{k-1}) - l_k R_k e_z | at sample 0.
double initialAxisError(const ChainSpec& s, const ChainTrajectory& tr) {
  double e = 0.0;
  for (std::size_t k = 0; k < s.length.size(); ++k)
    e = std::max(e, ((tr.ends[0][k + 1] - tr.ends[0][k]) - s.length[k] * s.rotation[k].col(2)).norm());
  return e;
}

// Independent energies of the initial state from the spec alone (z down: V = -g sum m z).
void specEnergy(const ChainSpec& s, double& V, double& T) {
  V = 0.0;
  T = 0.0;
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), vbase = Eigen::Vector3d::Zero();
  const std::size_t n = s.length.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d a = s.rotation[k].col(2), w = s.angular_velocity[k];
    const Eigen::Vector3d c = base + 0.5 * s.length[k] * a;
    const Eigen::Vector3d vc = vbase + w.cross(0.5 * s.length[k] * a);
    const Eigen::Matrix3d I = s.rotation[k] *
                              Eigen::Vector3d(s.inertia_transverse[k], s.inertia_transverse[k], s.inertia_polar[k])
                                  .asDiagonal() *
                              s.rotation[k].transpose();
    V -= s.gravity * s.mass[k] * c.z();
    T += 0.5 * s.mass[k] * vc.squaredNorm() + 0.5 * w.dot(I * w);
    vbase += w.cross(s.length[k] * a);
    base += s.length[k] * a;
  }
  V -= s.gravity * s.load_mass * base.z();
  T += 0.5 * s.load_mass * vbase.squaredNorm();
}

// Direct check of the qpos/qvel mapping against MuJoCo's own kinematics: load the generated
// model, write the initial state, run mj_forward and compare each link body's world rotation
// (xmat) and world angular velocity (mj_objectVelocity) with the spec.
void checkStateMapping(const ChainSpec& s, double& rot_err, double& omega_err) {
  const std::string xml = cable_reference::chainMjcf(s, 1e-3);
  const char* path = "/tmp/mujoco_chain_demo_model.xml";
  std::FILE* f = std::fopen(path, "w");
  if (!f) throw std::runtime_error("cannot write temp model");
  std::fwrite(xml.data(), 1, xml.size(), f);
  std::fclose(f);
  char err[1024] = {0};
  mjModel* m = mj_loadXML(path, nullptr, err, sizeof(err));
  std::remove(path);
  if (!m) throw std::runtime_error(err);
  mjData* d = mj_makeData(m);
  std::vector<double> qpos, qvel;
  cable_reference::chainInitialState(s, qpos, qvel);
  for (int i = 0; i < m->nq; ++i) d->qpos[i] = qpos[i];
  for (int i = 0; i < m->nv; ++i) d->qvel[i] = qvel[i];
  mj_forward(m, d);
  rot_err = omega_err = 0.0;
  for (std::size_t k = 0; k < s.length.size(); ++k) {
    const int b = mj_name2id(m, mjOBJ_BODY, ("link" + std::to_string(k + 1)).c_str());
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = d->xmat[9 * b + 3 * i + j];  // xmat is row-major
    rot_err = std::max(rot_err, (R - s.rotation[k]).norm());
    mjtNum v[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, b, v, 0);  // (angular, linear), world orientation
    omega_err = std::max(omega_err, (Eigen::Vector3d(v[0], v[1], v[2]) - s.angular_velocity[k]).norm());
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

// Mean period from upward zero crossings of x(t) (linear interpolation between samples).
double measuredPeriod(const ChainTrajectory& tr, int& crossings) {
  std::vector<double> tc;
  for (std::size_t i = 1; i < tr.time.size(); ++i) {
    const double x0 = tr.ends[i - 1][1].x(), x1 = tr.ends[i][1].x();
    if (x0 < 0.0 && x1 >= 0.0) tc.push_back(tr.time[i - 1] + (tr.time[i] - tr.time[i - 1]) * (-x0) / (x1 - x0));
  }
  crossings = static_cast<int>(tc.size());
  if (tc.size() < 2) return NAN;
  return (tc.back() - tc.front()) / static_cast<double>(tc.size() - 1);
}

void pendulumCase(const char* name, double load) {
  ChainSpec s;
  const double l = 0.8, m = 1.7, r = 0.04, theta0 = 0.01;
  addLink(s, l, m, r, rot(Eigen::Vector3d::UnitY(), theta0), Eigen::Vector3d::Zero());
  s.load_mass = load;
  const double dt = 1e-3;
  const ChainTrajectory tr = cable_reference::simulateChainInMujoco(s, dt, 20.0, dt);
  // Compound pendulum about the pivot: J = m l^2/4 + I_T + m_L l^2, restoring coefficient
  // k = (m l/2 + m_L l) g; T0 = 2 pi sqrt(J / k) (load 0: the formula of the brief).
  const double J = m * l * l / 4.0 + s.inertia_transverse[0] + load * l * l;
  const double kr = (m * l / 2.0 + load * l) * s.gravity;
  const double T0 = 2.0 * M_PI * std::sqrt(J / kr);
  int nc = 0;
  const double T = measuredPeriod(tr, nc);
  std::printf("%s: theta0 = %.3g rad, load = %.3g kg, %d crossings over 20 s\n", name, theta0, load, nc);
  std::printf("  T_measured = %.9f s, T_small_angle = %.9f s, T0 (1 + theta0^2/16) = %.9f s\n", T, T0,
              T0 * (1.0 + theta0 * theta0 / 16.0));
  check(std::abs(T / T0 - 1.0) < 1e-3, "period relative error vs small-angle formula", std::abs(T / T0 - 1.0),
        1e-3);
  std::printf("  (relative error vs amplitude-corrected period: %.3e)\n",
              std::abs(T / (T0 * (1.0 + theta0 * theta0 / 16.0)) - 1.0));
  check(lengthError(s, tr) < 1e-9, "link length error, all samples [m]", lengthError(s, tr), 1e-9);
  check(initialAxisError(s, tr) < 1e-12, "initial axis error [m]", initialAxisError(s, tr), 1e-12);
}

ChainSpec threeLinkSpec(bool moving) {
  ChainSpec s;
  // Tilted, non-planar configuration (axes not in a common vertical plane), each link also
  // rotated about its own axis so the transverse axes are generic.
  const Eigen::Matrix3d R1 = rot(Eigen::Vector3d(1, 0.3, 0), 0.7) * rot(Eigen::Vector3d::UnitZ(), 0.4);
  const Eigen::Matrix3d R2 = rot(Eigen::Vector3d(-0.2, 1, 0.1), 1.1) * rot(Eigen::Vector3d::UnitZ(), -1.3);
  const Eigen::Matrix3d R3 = rot(Eigen::Vector3d(0.6, -0.8, 0.3), 1.9) * rot(Eigen::Vector3d::UnitZ(), 2.2);
  Eigen::Vector3d w1 = Eigen::Vector3d::Zero(), w2 = w1, w3 = w1;
  if (moving) {
    // Transverse rates plus spin about each link's own axis (R.col(2)).
    w1 = Eigen::Vector3d(0.6, -0.4, 0.2) + 2.0 * R1.col(2);
    w2 = Eigen::Vector3d(-0.5, 0.9, 0.3) - 3.0 * R2.col(2);
    w3 = Eigen::Vector3d(1.2, 0.4, -0.7) + 4.0 * R3.col(2);
  }
  addLink(s, 0.5, 1.0, 0.03, R1, w1);
  addLink(s, 0.7, 1.5, 0.04, R2, w2);
  addLink(s, 0.4, 0.8, 0.025, R3, w3);
  s.load_mass = 0.3;
  return s;
}

double relativeDrift(const ChainTrajectory& tr, double* t_at = nullptr, double* kmax = nullptr) {
  const double E0 = tr.potential_energy[0] + tr.kinetic_energy[0];
  double drift = 0.0;
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    const double dE = std::abs(tr.potential_energy[i] + tr.kinetic_energy[i] - E0);
    if (dE > drift) {
      drift = dE;
      if (t_at) *t_at = tr.time[i];
    }
    if (kmax) *kmax = std::max(*kmax, tr.kinetic_energy[i]);
  }
  return drift / std::abs(E0);
}

void energyCase(const char* name, bool moving) {
  const ChainSpec s = threeLinkSpec(moving);
  const double dt = 1e-3;
  const ChainTrajectory tr = cable_reference::simulateChainInMujoco(s, dt, 5.0, dt);
  std::printf("%s: %zu samples, t_end = %.6f s\n", name, tr.time.size(), tr.time.back());

  double V0, T0;
  specEnergy(s, V0, T0);
  const double E0 = tr.potential_energy[0] + tr.kinetic_energy[0];
  std::printf("  initial energy: MuJoCo V = %.12f T = %.12f | from spec V = %.12f T = %.12f [J]\n",
              tr.potential_energy[0], tr.kinetic_energy[0], V0, T0);
  const double escale = std::abs(V0) + std::abs(T0);
  check(std::abs(tr.potential_energy[0] - V0) < 1e-12 * escale, "initial potential energy vs spec (rel)",
        std::abs(tr.potential_energy[0] - V0) / escale, 1e-12);
  check(std::abs(tr.kinetic_energy[0] - T0) < 1e-12 * escale, "initial kinetic energy vs spec (rel)",
        std::abs(tr.kinetic_energy[0] - T0) / escale, 1e-12);

  double tmax = 0.0, kmax = 0.0;
  const double rel = relativeDrift(tr, &tmax, &kmax);
  std::printf("  E0 = %.12f J, max kinetic = %.6f J, max |E - E0| / |E0| = %.3e at t = %.3f s\n", E0, kmax, rel,
              tmax);
  check(rel < 1e-6, "energy drift |E - E0| / |E0| over 5 s, dt = 1e-3", rel, 1e-6);
  check(lengthError(s, tr) < 1e-9, "link length error, all samples [m]", lengthError(s, tr), 1e-9);
  check(initialAxisError(s, tr) < 1e-12, "initial axis error [m]", initialAxisError(s, tr), 1e-12);

  double rerr, werr;
  checkStateMapping(s, rerr, werr);
  check(rerr < 1e-12, "MuJoCo xmat vs spec rotation (Frobenius)", rerr, 1e-12);
  check(werr < 1e-12, "MuJoCo body angular velocity vs spec [rad/s]", werr, 1e-12);

  // Convergence of the energy error with dt. MuJoCo's RK4 adds the stage velocities of a ball
  // joint linearly in the tangent space of the step's initial quaternion (no dexp^-1
  // correction), which makes it only second-order accurate once rotations do not commute
  // (non-planar motion); planar motion stays fourth order.
  const ChainTrajectory tr2 = cable_reference::simulateChainInMujoco(s, dt / 2, 5.0, dt);
  const double rel2 = relativeDrift(tr2);
  std::printf("  dt = 5e-4: drift %.3e; ratio drift(1e-3)/drift(5e-4) = %.2f -> observed order %.2f\n", rel2,
              rel / rel2, std::log2(rel / rel2));
  const double dt_small = 5e-5;
  const ChainTrajectory tr3 = cable_reference::simulateChainInMujoco(s, dt_small, 5.0, dt);
  const double rel3 = relativeDrift(tr3);
  check(rel3 < 1e-6, "energy drift over 5 s, dt = 5e-5", rel3, 1e-6);
  check(lengthError(s, tr3) < 1e-9, "link length error, dt = 5e-5 [m]", lengthError(s, tr3), 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("MuJoCo %s (library %d, header %d)\n", mj_versionString(), mj_version(), mjVERSION_HEADER);
  if (argc > 1 && std::strcmp(argv[1], "--print-mjcf") == 0) {
    ChainSpec s;
    addLink(s, 0.5, 1.0, 0.03, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    addLink(s, 0.7, 1.5, 0.04, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    s.load_mass = 0.3;
    std::fputs(cable_reference::chainMjcf(s, 1e-3).c_str(), stdout);
    return 0;
  }
  try {
    pendulumCase("n = 1 compound pendulum", 0.0);
    pendulumCase("n = 1 compound pendulum with end load", 0.5);
    energyCase("n = 3, non-planar, with angular velocities incl. spin", true);
    energyCase("n = 3, non-planar, released at rest", false);
    // Error path: a model MuJoCo refuses (polar > 2 x transverse violates A + B >= C).
    ChainSpec bad = threeLinkSpec(false);
    bad.inertia_polar[1] = 10.0;
    try {
      cable_reference::simulateChainInMujoco(bad, 1e-3, 0.01, 1e-3);
      check(false, "invalid inertia rejected with std::runtime_error", 0.0, 0.0);
    } catch (const std::runtime_error& e) {
      std::printf("invalid model -> std::runtime_error: %s\n", e.what());
    }
  } catch (const std::exception& e) {
    std::printf("EXCEPTION: %s\n", e.what());
    return 2;
  }
  std::printf(g_failures ? "%d CHECK(S) FAILED\n" : "ALL CHECKS PASSED\n", g_failures);
  return g_failures ? 1 : 0;
}
