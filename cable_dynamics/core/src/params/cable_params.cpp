#include "cable_dynamics/params/cable_params.h"

#include <cmath>
#include <numeric>

namespace cable_dynamics {

double CableParams::totalLength() const {
  return std::accumulate(link_lengths.begin(), link_lengths.end(), 0.0);
}

double CableParams::deployedLength() const {
  return std::accumulate(link_lengths.begin() + winch.stored_links, link_lengths.end(), 0.0);
}

LinkProperties deriveLinkProperties(const CableParams& params) {
  const int n = params.links;
  const double radius = 0.5 * params.diameter;                  // [m]
  const double section_area = M_PI * radius * radius;           // [m^2]
  LinkProperties p;
  p.n = n;
  p.radius = radius;
  p.length = Eigen::Map<const Eigen::VectorXd>(params.link_lengths.data(), n);
  p.mass = params.mass_per_length * p.length;
  // A link is a solid cylinder of the cable's outer diameter: the transverse inertia is about the CoM.
  p.inertia_transverse = p.mass.array() * (p.length.array().square() / 12.0 + radius * radius / 4.0);
  p.inertia_polar = p.mass * (radius * radius / 2.0);
  p.submerged_mass = p.mass - params.fluid.density * section_area * p.length;
  p.added_mass_per_length = params.fluid.added_mass * params.fluid.density * section_area;

  // Rigidities, when given, give per-joint springs k = EI / s_k, s_k the arc length the joint's bend is
  // spread over: between the centres of the two links it joins, (l_{k-1} + l_k)/2, and for joint 1 from
  // the clamp to link 1's centre, l_1/2. (A whole l_1 there makes the clamp first-order accurate: a
  // cantilever's tip deflection off by about 2/n; docs/MODEL.md section 5.)
  const StiffnessParams& k = params.stiffness;
  Eigen::VectorXd inv_length(n);
  for (int j = 0; j < n; ++j) inv_length(j) = 2.0 / (p.length(j) + (j > 0 ? p.length(j - 1) : 0.0));
  const auto springs = [&](double per_joint, double rigidity) -> Eigen::VectorXd {
    return rigidity > 0.0 ? Eigen::VectorXd(rigidity * inv_length) : Eigen::VectorXd::Constant(n, per_joint);
  };
  p.stiffness_elevation = springs(k.elevation, k.bending_rigidity);
  p.stiffness_azimuth = springs(k.azimuth, k.bending_rigidity);
  p.stiffness_torsion = springs(k.torsion, k.torsional_rigidity);
  p.damping_elevation = Eigen::VectorXd::Constant(n, params.damping.elevation);
  p.damping_azimuth = Eigen::VectorXd::Constant(n, params.damping.azimuth);
  p.damping_torsion = Eigen::VectorXd::Constant(n, params.damping.torsion);
  // The base: a pin holds link 1 by a force alone; a clamp along base.direction (world) by joint 1.
  if (params.base.fixity == BaseFixity::kPinned) {
    for (Eigen::VectorXd* v : {&p.stiffness_elevation, &p.stiffness_azimuth, &p.stiffness_torsion, &p.damping_elevation,
                               &p.damping_azimuth, &p.damping_torsion}) {
      (*v)(0) = 0.0;
    }
  }
  const Eigen::Vector3d& d = params.base.direction;  // world, z up
  p.clamp_axis = Eigen::Vector3d(d.x(), -d.y(), -d.z()).normalized();  // paper frame, z down
  p.clamp_twist = std::hypot(p.clamp_axis.x(), p.clamp_axis.y()) > 1e-12 ? std::atan2(p.clamp_axis.x(), p.clamp_axis.y()) : 0.0;

  p.load_mass = params.load.mass;
  p.load_submerged_mass = params.load.mass - params.fluid.density * params.load.volume;
  p.gravity = params.gravity;
  p.stiffness_model = k.model;
  return p;
}

const char* integratorName(Integrator integrator) {
  return integrator == Integrator::kRk4 ? "rk4" : "semi_implicit";
}

const char* formulationName(Formulation formulation) {
  return formulation == Formulation::kRecursive ? "recursive" : "paper";
}

std::string coordinateName(int index) {
  static const char* const kDirection[3] = {"elevation", "azimuth", "torsion"};
  return "joint_" + std::to_string(index / 3 + 1) + "_" + kDirection[index % 3];
}

std::vector<std::string> coordinateNames(int links) {
  std::vector<std::string> names;
  names.reserve(3 * links);
  for (int i = 0; i < 3 * links; ++i) names.push_back(coordinateName(i));
  return names;
}

}  // namespace cable_dynamics
