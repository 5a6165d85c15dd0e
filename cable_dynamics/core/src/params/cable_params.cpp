#include "cable_dynamics/params/cable_params.h"

#include <cmath>
#include <algorithm>
#include <numeric>

namespace cable_dynamics {

double CableParams::totalLength() const {
  return std::accumulate(link_lengths.begin(), link_lengths.end(), 0.0);
}

int drumSlotsFor(const WinchParams& w, double deployed) {
  return static_cast<int>(std::ceil((w.max_length - deployed) / w.link_length - 1e-9)) + 1;
}

double CableParams::deployedLength() const {
  return std::accumulate(link_lengths.begin() + drumSlots(), link_lengths.end(), 0.0);
}

bool CableParams::stretches() const {
  bool any = axial_stiffness > 0.0;
  for (const SectionParams& s : sections) any = any || s.axial_stiffness > 0.0;
  return any;
}

static std::vector<SectionParams> effectiveSections(const CableParams& params) {
  if (!params.sections.empty()) return params.sections;
  SectionParams s;
  s.length = params.deployedLength();
  s.diameter = params.diameter;
  s.mass_per_length = params.mass_per_length;
  s.bending_rigidity = params.stiffness.bending_rigidity;
  s.torsional_rigidity = params.stiffness.torsional_rigidity;
  s.axial_stiffness = params.axial_stiffness;
  s.drag_normal = params.fluid.drag_normal;
  s.drag_tangential = params.fluid.drag_tangential;
  s.added_mass = params.fluid.added_mass;
  s.min_bend_radius = params.limits.min_bend_radius;
  return {s};
}

LinkProperties deriveLinkProperties(const CableParams& params) {
  const int n = params.links, stored = params.drumSlots();
  const double rho = params.fluid.density;
  const std::vector<SectionParams> sections = effectiveSections(params);
  LinkProperties p;
  p.n = n;
  p.length = Eigen::Map<const Eigen::VectorXd>(params.link_lengths.data(), n);
  // Each link takes the section its centre lies in, by arc length from the base of the configured
  // cable; the drum's slots (a winch) take the base section's.
  p.section.setZero(n);
  {
    double start = 0.0;  // arc length of the configured cable at the slot's base end [m]
    std::size_t s = 0;
    double section_end = sections[0].length;
    for (int k = stored; k < n; ++k) {
      const double centre = start + 0.5 * p.length(k);
      while (s + 1 < sections.size() && centre >= section_end) section_end += sections[++s].length;
      p.section(k) = static_cast<int>(s);
      start += p.length(k);
    }
  }
  // The limits: each link's minimum bend radius is its section's (the drum's slots take the base section's).
  p.min_bend_radius.resize(n);
  for (int k = 0; k < n; ++k) p.min_bend_radius(k) = sections[p.section(k)].min_bend_radius;
  p.max_tension = params.limits.max_tension;
  p.min_seabed_clearance = params.limits.has_min_seabed_clearance ? params.limits.min_seabed_clearance : -1.0;
  p.radius.resize(n);
  p.mass.resize(n);
  p.submerged_mass.resize(n);
  p.added_mass_per_length.resize(n);
  p.drag_normal.resize(n);
  p.drag_tangential.resize(n);
  p.axial_stiffness.resize(n);
  p.axial_damping = params.axial_damping;
  Eigen::VectorXd bending(n), torsional(n);
  for (int k = 0; k < n; ++k) {
    const SectionParams& sec = sections[p.section(k)];
    const double radius = 0.5 * sec.diameter, area = M_PI * radius * radius;  // [m], [m^2]
    p.radius(k) = radius;
    p.mass(k) = sec.mass_per_length * p.length(k);
    p.submerged_mass(k) = p.mass(k) - rho * area * p.length(k);
    p.added_mass_per_length(k) = sec.added_mass * rho * area;
    p.drag_normal(k) = sec.drag_normal;
    p.drag_tangential(k) = sec.drag_tangential;
    p.axial_stiffness(k) = sec.axial_stiffness > 0.0 ? sec.axial_stiffness : params.axial_stiffness;
    bending(k) = sec.bending_rigidity;
    torsional(k) = sec.torsional_rigidity;
  }
  // A link is a solid cylinder of its section's outer diameter: the transverse inertia is about the CoM.
  const Eigen::ArrayXd r2 = p.radius.array().square();
  p.inertia_transverse = p.mass.array() * (p.length.array().square() / 12.0 + r2 / 4.0);
  p.inertia_polar = p.mass.array() * (r2 / 2.0);

  // Attachments: on the slot that holds the arc length (a point on a link end belongs to the link
  // outboard of it; the tip to the last link), at that distance from its base end.
  std::vector<AttachmentParams> attachments = params.attachments;
  std::stable_sort(attachments.begin(), attachments.end(),
                   [](const AttachmentParams& a, const AttachmentParams& b) { return a.arc_length < b.arc_length; });
  {
    int k = stored;
    double start = 0.0;
    for (const AttachmentParams& a : attachments) {
      while (k + 1 < n && a.arc_length >= start + p.length(k)) start += p.length(k++);
      LinkAttachment la;
      la.link = k;
      la.offset = std::min(std::max(a.arc_length - start, 0.0), p.length(k));
      la.mass = a.mass;
      la.submerged_mass = a.mass - rho * a.volume;
      la.added_mass = a.added_mass;
      la.drag_area = a.drag_area;
      p.attachments.push_back(la);
    }
  }

  // Rigidities, when given, give per-joint springs k = EI / s_k, s_k the arc length the joint's bend is
  // spread over: between the centres of the two links it joins, (l_{k-1} + l_k)/2, and for joint 1 from
  // the clamp to link 1's centre, l_1/2. (A whole l_1 there makes the clamp first-order accurate: a
  // cantilever's tip deflection off by about 2/n; docs/MODEL.md section 5.)
  const StiffnessParams& k = params.stiffness;
  // Per link the rigidity of its section; joint j's bend is spread over half of each link it joins,
  // which with different rigidities are springs in series: 1/k = (l_{j-1}/2)/EI_{j-1} + (l_j/2)/EI_j
  // (exact for a piecewise-uniform beam under a uniform moment; 2 EI/(l_{j-1} + l_j) when they agree).
  const auto springs = [&](double per_joint, const Eigen::VectorXd& rigidity) -> Eigen::VectorXd {
    if (!(rigidity.array() > 0.0).any()) return Eigen::VectorXd::Constant(n, per_joint);
    Eigen::VectorXd out(n);
    for (int j = 0; j < n; ++j) {
      const double own = rigidity(j);
      if (j == 0) {
        out(j) = own * (2.0 / p.length(0));
      } else if (rigidity(j - 1) == own) {
        out(j) = own * (2.0 / (p.length(j) + p.length(j - 1)));
      } else if (own > 0.0 && rigidity(j - 1) > 0.0) {
        out(j) = 1.0 / (0.5 * p.length(j - 1) / rigidity(j - 1) + 0.5 * p.length(j) / own);
      } else {
        out(j) = 0.0;
      }
    }
    return out;
  };
  p.stiffness_elevation = springs(k.elevation, bending);
  p.stiffness_azimuth = springs(k.azimuth, bending);
  p.stiffness_torsion = springs(k.torsion, torsional);
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
  p.clamped_base = k.model == StiffnessModel::kBending && params.base.fixity == BaseFixity::kClamped;
  p.clamped_tip = params.load.fixity == TipFixity::kClamped;
  const Eigen::Vector3d& d = params.base.direction;  // world, z up
  p.clamp_axis = Eigen::Vector3d(d.x(), -d.y(), -d.z()).normalized();  // paper frame, z down
  p.clamp_twist = std::hypot(p.clamp_axis.x(), p.clamp_axis.y()) > 1e-12 ? std::atan2(p.clamp_axis.x(), p.clamp_axis.y()) : 0.0;

  // A clamped tip: the last link's half, l_n / 2, to the clamp (the joint springs' rule at the base).
  if (params.load.fixity == TipFixity::kClamped && n > 0) {
    const double rigidity = bending(n - 1);
    p.tip_clamp_stiffness = rigidity > 0.0 ? rigidity * (2.0 / p.length(n - 1)) : 2.0 * k.elevation;
    p.tip_clamp_damping = params.damping.elevation;
    const Eigen::Vector3d& t = params.load.direction;  // world (anchored) or the ROV's frame at rest (attached)
    p.tip_clamp_axis = Eigen::Vector3d(t.x(), -t.y(), -t.z()).normalized();
  }
  p.load_mass = params.load.mass;
  p.load_submerged_mass = params.load.mass - params.fluid.density * params.load.volume;
  p.gravity = params.gravity;
  p.stiffness_model = k.model;
  return p;
}

const char* integratorName(Integrator integrator) {
  switch (integrator) {
    case Integrator::kRk4:
      return "rk4";
    case Integrator::kSemiImplicit:
      return "semi_implicit";
    case Integrator::kImplicit:
      return "implicit";
  }
  return "rk4";
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
