#include "chain_spec.h"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

namespace bench {

namespace {
/// The benchmark chain: the default umbilical's 50 m, 25 mm, 0.6 kg/m cable with a 10 kg point load,
/// in air (no fluid), no springs or dampers, fixed base.
constexpr double kTotalLength = 50.0;    // [m]
constexpr double kDiameter = 0.025;      // [m]
constexpr double kMassPerLength = 0.6;   // [kg/m]
constexpr double kLoadMass = 10.0;       // [kg]
constexpr double kTilt = 0.3;            // elevation of every link from the downward vertical [rad]
/// The absolute azimuth turns evenly from 0 at the base to this at the tip: a smooth, non-planar curve.
/// (Not alternating azimuths: a zigzag is a violent start for fine chains, its kinks snap straight
/// faster than RK4 at dt = 1 ms resolves: at n = 300 every system loses energy conservation past 1e-3
/// within 0.1 s and blows up near 0.2 s.)
constexpr double kAzimuthTurn = 1.0;     // [rad]
}  // namespace

std::string projectConfig(int links) {
  std::ostringstream y;
  y.precision(17);
  y << "cable:\n"
    << "  links: " << links << "\n"
    << "  length: " << kTotalLength << "\n"
    << "  diameter: " << kDiameter << "\n"
    << "  mass_per_length: " << kMassPerLength << "\n"
    << "  stiffness: {model: paper, elevation: 0.0, azimuth: 0.0, torsion: 0.0}\n"
    << "  damping: {elevation: 0.0, azimuth: 0.0, torsion: 0.0}\n"
    << "load: {mass: " << kLoadMass << ", volume: 0.0, mode: free}\n"
    << "fluid: {density: 0.0, current: [0.0, 0.0, 0.0]}\n"
    << "gravity: 9.81\n"
    << "initial:\n"
    << "  elevation: " << kTilt << "\n"
    // The config's azimuths are relative to the previous link: 0, then turn / (n - 1) each.
    << "  azimuth: [";
  for (int k = 0; k < links; ++k) y << (k ? ", " : "") << (k == 0 || links == 1 ? 0.0 : kAzimuthTurn / (links - 1));
  y << "]\n"
    << "  torsion: 0.0\n"
    << "simulation: {dt: 0.001, integrator: rk4}\n";
  return y.str();
}

ChainSpec makeSpec(const cable_dynamics::CableParams& params, const std::vector<Eigen::Vector3d>& axes) {
  const cable_dynamics::LinkProperties p = cable_dynamics::deriveLinkProperties(params);
  ChainSpec s;
  s.n = p.n;
  s.dt = params.simulation.dt;
  s.gravity = p.gravity;
  s.load_mass = p.load_mass;
  for (int k = 0; k < p.n; ++k) {
    s.length.push_back(p.length(k));
    s.mass.push_back(p.mass(k));
    s.inertia_transverse.push_back(p.inertia_transverse(k));
    s.inertia_polar.push_back(p.inertia_polar(k));
    // Any rotation taking e_z to the axis will do: the links are axisymmetric and start at rest.
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axes[k].normalized());
    s.rotation.push_back(q.toRotationMatrix());
  }
  return s;
}

double ChainSpec::bodyMass(int k) const { return mass[k] + (k == n - 1 ? load_mass : 0.0); }

double ChainSpec::bodyCom(int k) const {
  const double l = length[k];
  if (k != n - 1 || load_mass == 0.0) return 0.5 * l;
  return (mass[k] * 0.5 * l + load_mass * l) / (mass[k] + load_mass);
}

double ChainSpec::bodyInertiaTransverse(int k) const {
  if (k != n - 1 || load_mass == 0.0) return inertia_transverse[k];
  // Parallel axes: the link about the new centre of mass, plus the load as a point mass.
  const double l = length[k], c = bodyCom(k);
  return inertia_transverse[k] + mass[k] * (0.5 * l - c) * (0.5 * l - c) + load_mass * (l - c) * (l - c);
}

Eigen::Matrix3d ChainSpec::relativeRotation(int k) const {
  return k == 0 ? rotation[0] : Eigen::Matrix3d(rotation[k - 1].transpose() * rotation[k]);
}

double ChainSpec::releasableEnergy() const {
  // Potential -m g z (z down). At the start each centre of mass is at its depth; hanging, along the axis.
  double start = 0.0, hanging = 0.0, depth_start = 0.0, depth_hanging = 0.0;
  for (int k = 0; k < n; ++k) {
    const double axial = rotation[k](2, 2);  // z component of the axis
    start -= gravity * mass[k] * (depth_start + 0.5 * length[k] * axial);
    hanging -= gravity * mass[k] * (depth_hanging + 0.5 * length[k]);
    depth_start += length[k] * axial;
    depth_hanging += length[k];
  }
  start -= gravity * load_mass * depth_start;
  hanging -= gravity * load_mass * depth_hanging;
  return start - hanging;
}

}  // namespace bench
