// MuJoCo reference for a chain of rigid links on ball joints. See mujoco_chain.h.
#include "mujoco_chain.h"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace cable_reference {
namespace {

std::size_t checkSpec(const ChainSpec& s) {
  const std::size_t n = s.length.size();
  if (n == 0) throw std::invalid_argument("ChainSpec: at least one link is required");
  if (s.mass.size() != n || s.inertia_transverse.size() != n || s.inertia_polar.size() != n ||
      s.rotation.size() != n || s.angular_velocity.size() != n)
    throw std::invalid_argument("ChainSpec: all per-link vectors must have the same size as `length`");
  for (std::size_t k = 0; k < n; ++k) {
    if (!(s.length[k] > 0.0)) throw std::invalid_argument("ChainSpec: link lengths must be positive");
    if (!(s.mass[k] > 0.0)) throw std::invalid_argument("ChainSpec: link masses must be positive");
  }
  if (!(s.load_mass >= 0.0)) throw std::invalid_argument("ChainSpec: load_mass must be >= 0");
  return n;
}

// World orientation of each link as a unit quaternion (the given matrices are projected
// onto the nearest rotation through Eigen's matrix -> quaternion conversion + normalisation).
std::vector<Eigen::Quaterniond> worldQuaternions(const ChainSpec& s) {
  std::vector<Eigen::Quaterniond> q;
  q.reserve(s.rotation.size());
  for (const auto& R : s.rotation) q.push_back(Eigen::Quaterniond(R).normalized());
  return q;
}

struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};
struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

}  // namespace

std::string chainMjcf(const ChainSpec& spec, double dt) {
  const std::size_t n = checkSpec(spec);
  std::ostringstream x;
  x << std::setprecision(17);

  x << "<mujoco model=\"cable_reference_chain\">\n";
  // inertiafromgeom=false: only the explicit <inertial> elements define mass properties;
  // no bounding / balancing / rescaling of masses and inertias by the compiler.
  x << "  <compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\""
       " balanceinertia=\"false\" settotalmass=\"-1\"/>\n";
  // z-down world: gravity along +z. No medium (density/viscosity/wind = 0).
  x << "  <option timestep=\"" << dt << "\" integrator=\"RK4\" gravity=\"0 0 " << spec.gravity
    << "\" wind=\"0 0 0\" density=\"0\" viscosity=\"0\">\n";
  // Nothing dissipative or constraining: no contacts, no constraint solver at all (a ball
  // joint chain without limits has no constraints), no passive forces (springs, damping,
  // fluid). Energy computation enabled for diagnostics.
  x << "    <flag contact=\"disable\" constraint=\"disable\" equality=\"disable\" frictionloss=\"disable\""
       " limit=\"disable\" passive=\"disable\" actuation=\"disable\" gravity=\"enable\" energy=\"enable\"/>\n";
  x << "  </option>\n";
  x << "  <worldbody>\n";

  std::string indent = "    ";
  for (std::size_t k = 0; k < n; ++k) {
    const double l = spec.length[k];
    // Every link body's frame has its origin at the link's base end (= the ball joint) and
    // its z axis along the link axis in the reference pose (qpos = identity quaternions:
    // the chain hangs straight down along +z). The child body sits at (0, 0, l) of its parent.
    const double pz = (k == 0) ? 0.0 : spec.length[k - 1];
    x << indent << "<body name=\"link" << k + 1 << "\" pos=\"0 0 " << pz << "\" quat=\"1 0 0 0\">\n";
    const std::string in = indent + "  ";
    x << in << "<joint name=\"ball" << k + 1 << "\" type=\"ball\" pos=\"0 0 0\" limited=\"false\""
        << " damping=\"0\" armature=\"0\" frictionloss=\"0\" stiffness=\"0\"/>\n";

    // Mass properties. Link alone: mass m at (0, 0, l/2), diagonal inertia (I_T, I_T, I_P).
    // Last link with a point load m_L at its far end (0, 0, l): fold the load into the link's
    // inertial (a separate body would need strictly positive inertia, i.e. it would not be a
    // point mass):
    //   M   = m + m_L
    //   c   = (m l/2 + m_L l) / M                                   (combined CoM on the axis)
    //   I_T' = I_T + m (l/2 - c)^2 + m_L (l - c)^2                  (parallel-axis theorem, about c)
    //   I_P' = I_P                                                  (the load lies on the axis)
    double M = spec.mass[k];
    double c = 0.5 * l;
    double IT = spec.inertia_transverse[k];
    const double IP = spec.inertia_polar[k];
    if (k + 1 == n && spec.load_mass > 0.0) {
      const double m = spec.mass[k], mL = spec.load_mass;
      M = m + mL;
      c = (m * 0.5 * l + mL * l) / M;
      IT = IT + m * (0.5 * l - c) * (0.5 * l - c) + mL * (l - c) * (l - c);
    }
    x << in << "<inertial pos=\"0 0 " << c << "\" quat=\"1 0 0 0\" mass=\"" << M << "\" diaginertia=\"" << IT
      << " " << IT << " " << IP << "\"/>\n";
    // Geometry only for completeness (no contacts, no mass contribution).
    x << in << "<geom type=\"capsule\" fromto=\"0 0 0 0 0 " << l << "\" size=\"" << 0.02 * l
      << "\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>\n";
    // Marker at the far end of the link: its world position is what we sample.
    x << in << "<site name=\"end" << k + 1 << "\" pos=\"0 0 " << l << "\" size=\"" << 0.01 * l << "\"/>\n";
    indent = in;
  }
  for (std::size_t k = n; k-- > 0;) {
    indent.resize(indent.size() - 2);
    x << indent << "</body>\n";
  }
  x << "  </worldbody>\n";
  x << "</mujoco>\n";
  return x.str();
}

// Mapping of the world-frame initial state onto MuJoCo's joint coordinates.
//
// Orientation. Let R_k be the world orientation of link k (MuJoCo's xmat of body k), R_0 = I
// (world). Body k is declared with quat = identity relative to body k-1, and its ball joint
// rotates it by the joint quaternion Q_k (qpos), so MuJoCo's kinematics give
//     R_k = R_{k-1} * (body quat = I) * Q_k   =>   Q_k = R_{k-1}^T R_k,
// in quaternion form q_k = conj(qw_{k-1}) * qw_k with qw_k the world quaternion of link k.
// MuJoCo stores quaternions as (w, x, y, z).
//
// Angular velocity. MuJoCo integrates a ball joint as Q <- Q * exp(dt/2 * qvel) (right
// multiplication), i.e. dQ_k/dt = Q_k [v_k]x with v_k = qvel_k: the rotation rate of link k
// relative to link k-1, expressed in link k's own (child) frame. Differentiating
// R_k = R_{k-1} Q_k:
//     dR_k/dt = [w_{k-1}]x R_{k-1} Q_k + R_{k-1} Q_k [v_k]x = ([w_{k-1}]x + [R_k v_k]x) R_k,
// hence w_k = w_{k-1} + R_k v_k and
//     qvel_k = R_k^T (w_k - w_{k-1}),   w_0 = 0 (fixed base).
// R_k here is the rotation of the (normalised) quaternion actually written into qpos.
void chainInitialState(const ChainSpec& spec, std::vector<double>& qpos, std::vector<double>& qvel) {
  const std::size_t n = checkSpec(spec);
  const std::vector<Eigen::Quaterniond> qw = worldQuaternions(spec);
  qpos.assign(4 * n, 0.0);
  qvel.assign(3 * n, 0.0);
  Eigen::Quaterniond parent = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_parent = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Quaterniond rel = (parent.conjugate() * qw[k]).normalized();
    qpos[4 * k + 0] = rel.w();
    qpos[4 * k + 1] = rel.x();
    qpos[4 * k + 2] = rel.y();
    qpos[4 * k + 3] = rel.z();
    const Eigen::Vector3d v = qw[k].toRotationMatrix().transpose() * (spec.angular_velocity[k] - w_parent);
    qvel[3 * k + 0] = v.x();
    qvel[3 * k + 1] = v.y();
    qvel[3 * k + 2] = v.z();
    parent = qw[k];
    w_parent = spec.angular_velocity[k];
  }
}

ChainTrajectory simulateChainInMujoco(const ChainSpec& spec, double dt, double duration, double sample_every) {
  const std::size_t n = checkSpec(spec);
  if (!(dt > 0.0)) throw std::invalid_argument("simulateChainInMujoco: dt must be positive");
  if (!(sample_every > 0.0)) throw std::invalid_argument("simulateChainInMujoco: sample_every must be positive");
  if (!(duration >= 0.0)) throw std::invalid_argument("simulateChainInMujoco: duration must be >= 0");
  if (mj_version() != mjVERSION_HEADER) {
    std::ostringstream e;
    e << "MuJoCo header version " << mjVERSION_HEADER << " does not match library version " << mj_version();
    throw std::runtime_error(e.str());
  }

  // Load the MJCF from memory through MuJoCo's virtual file system (mjVFS is a ~2 MB struct:
  // allocate it on the heap).
  const std::string xml = chainMjcf(spec, dt);
  const char* fname = "cable_reference_chain.xml";
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), fname, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: could not create the in-memory model file");
  const int fi = mj_findFileVFS(vfs.get(), fname);
  if (fi < 0) throw std::runtime_error("MuJoCo: in-memory model file not found");
  std::memcpy(vfs->filedata[fi], xml.data(), xml.size());

  char err[1024] = {0};
  std::unique_ptr<mjModel, ModelDeleter> m(mj_loadXML(fname, vfs.get(), err, sizeof(err)));
  if (!m) throw std::runtime_error(std::string("MuJoCo failed to load the chain model: ") + err);
  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m.get()));
  if (!d) throw std::runtime_error("MuJoCo: mj_makeData failed");
  if (m->nq != static_cast<int>(4 * n) || m->nv != static_cast<int>(3 * n))
    throw std::runtime_error("MuJoCo chain model has unexpected nq / nv");

  std::vector<int> site(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string name = "end" + std::to_string(k + 1);
    site[k] = mj_name2id(m.get(), mjOBJ_SITE, name.c_str());
    if (site[k] < 0) throw std::runtime_error("MuJoCo chain model: missing site " + name);
  }

  std::vector<double> qpos, qvel;
  chainInitialState(spec, qpos, qvel);
  // Joint k's addresses: with only ball joints, in order, qposadr = 4k and dofadr = 3k; read
  // them from the model anyway.
  for (std::size_t k = 0; k < n; ++k) {
    const int qa = m->jnt_qposadr[k], va = m->jnt_dofadr[k];
    for (int i = 0; i < 4; ++i) d->qpos[qa + i] = qpos[4 * k + i];
    for (int i = 0; i < 3; ++i) d->qvel[va + i] = qvel[3 * k + i];
  }
  d->time = 0.0;

  const long long steps_per_sample = std::max(1LL, std::llround(sample_every / dt));
  const long long total_steps = std::llround(duration / dt);

  ChainTrajectory out;
  auto record = [&](long long step) {
    // After mj_step (RK4) the derived quantities in mjData belong to the last RK stage, not to
    // the new state: recompute them for the current (qpos, qvel) before reading.
    mj_forward(m.get(), d.get());
    mj_energyPos(m.get(), d.get());
    mj_energyVel(m.get(), d.get());
    std::vector<Eigen::Vector3d> e(n + 1);
    e[0] = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < n; ++k) {
      const mjtNum* p = d->site_xpos + 3 * site[k];
      e[k + 1] = Eigen::Vector3d(p[0], p[1], p[2]);
    }
    out.time.push_back(static_cast<double>(step) * dt);
    out.ends.push_back(std::move(e));
    out.potential_energy.push_back(d->energy[0]);
    out.kinetic_energy.push_back(d->energy[1]);
  };

  record(0);
  for (long long step = 1; step <= total_steps; ++step) {
    mj_step(m.get(), d.get());
    if (step % steps_per_sample == 0) record(step);
  }
  // MuJoCo silently resets the state on NaN/Inf; make that an error instead.
  if (d->warning[mjWARN_BADQPOS].number || d->warning[mjWARN_BADQVEL].number || d->warning[mjWARN_BADQACC].number)
    throw std::runtime_error("MuJoCo reported a numerical instability (bad qpos/qvel/qacc) during the simulation");
  return out;
}

}  // namespace cable_reference
