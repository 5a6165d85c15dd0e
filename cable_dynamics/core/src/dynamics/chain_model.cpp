#include "cable_dynamics/dynamics/chain_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cable_dynamics {

CableParams ChainModel::withDrumSlots(const CableParams& configured) {
  CableParams p = configured;
  if (!p.winch.enabled || p.winch.slots_built) return p;
  const int stored = p.winch.stored_links;
  p.links += stored;
  p.link_lengths.insert(p.link_lengths.begin(), stored, p.winch.link_length);
  for (std::vector<double>* v : {&p.initial.elevation, &p.initial.azimuth, &p.initial.torsion}) {
    v->insert(v->begin(), stored, 0.0);  // on the drum: straight down, at rest (no length, no mass)
  }
  p.winch.slots_built = true;
  return p;
}

ChainModel::ChainModel(const CableParams& configured) : ChainModel(withDrumSlots(configured), 0) {}

ChainModel::ChainModel(const CableParams& params, int /*slots built*/)
    : n_(params.links),
      has_winch_(params.winch.enabled),
      far_points_(farPoints(params)),
      nominal_(deriveLinkProperties(params)),
      formulation_(params.simulation.formulation),
      fluid_density_(params.fluid.density),
      drag_(params.fluid),
      seabed_(makeSeabedContact(params, nominal_)),
      points_(params.links),
      attachment_begin_(params.links + 1, 0) {
  const LinkProperties& p = nominal_;
  for (const LinkAttachment& a : p.attachments) {
    PointSums& sums = points_[a.link];
    const double s = a.offset;
    sums.mass0 += a.mass;
    sums.mass1 += a.mass * s;
    sums.mass2 += a.mass * s * s;
    sums.added0 += a.added_mass;
    sums.added1 += a.added_mass * s;
    sums.added2 += a.added_mass * s * s;
    sums.sub0 += a.submerged_mass;
    sums.sub1 += a.submerged_mass * s;
    ++attachment_begin_[a.link + 1];
    attachment_drag_ = attachment_drag_ || (a.drag_area > 0.0 && params.fluid.density > 0.0);
  }
  for (int k = 0; k < n_; ++k) attachment_begin_[k + 1] += attachment_begin_[k];
  fold_stop_tension_ = FoldStop::tensionOf(p);
  has_springs_ = p.stiffness_elevation.any() || p.stiffness_azimuth.any() || p.stiffness_torsion.any() ||
                 p.damping_elevation.any() || p.damping_azimuth.any() || p.damping_torsion.any();
  // An ROV body carries its own mass, weight and drag (rov_body.h): the tip then holds no point load.
  body_ = RovBodyConstants::make(params.load, params.fluid.density, params.gravity);
  const bool point_load = !body_.active;
  load_.mass = point_load ? p.load_mass : 0.0;
  load_.inertia = point_load ? p.load_mass + params.load.added_mass : 0.0;
  load_.weight = point_load ? p.gravity * p.load_submerged_mass : 0.0;
  load_.drag_area = params.load.drag_area;
  load_.coupling_stiffness = params.load.coupling_stiffness;
  load_.coupling_damping = params.load.coupling_damping;
  if (params.load.heldExactly() && n_ > 0) {
    // An exact anchor (docs/MODEL.md section 14): RK4 on the recursion solves for the hold's force; the
    // other steps get the internal hold as the coupling, critically damped on the tip's share of mass.
    held_tip_ = params.simulation.integrator == Integrator::kRk4 && params.simulation.formulation == Formulation::kRecursive;
    hold_time_constant_ = params.simulation.dt;
    const double length = p.length.sum(), mass = p.mass.sum() + p.load_mass;
    hold_stiffness_ = length > 0.0 ? 1e6 * p.gravity * mass / length : 0.0;
    const double tip_mass = load_.inertia + p.mass(n_ - 1);
    load_.coupling_stiffness = held_tip_ ? 0.0 : hold_stiffness_;
    load_.coupling_damping = held_tip_ ? 0.0 : 2.0 * std::sqrt(hold_stiffness_ * tip_mass);
  }
  axial_ = p.axial_stiffness.size() > 0 && p.axial_stiffness.maxCoeff() > 0.0;
  last_locked_ = !(load_.inertia > 0.0) && !body_.active;
  initial_first_ = params.drumSlots();
}

ChainDeployment ChainModel::initialDeployment() const {
  ChainDeployment d;
  d.properties_ = nominal_;
  // Padding lanes past the last link: zero length and mass, 1/I_P = 0; they add nothing anywhere.
  d.lanes_.assign((n_ + kBlockLanes - 1) / kBlockLanes, LinkConstants{});
  deploy(d, initial_first_);
  return d;
}

void ChainModel::redeploy(ChainDeployment& d) const {
  if (d.properties_.length.size() != n_) {
    throw std::invalid_argument("cable.links = " + std::to_string(n_) + ": a retuned model must keep the " +
                                std::to_string(d.properties_.length.size()) + " links of the running one");
  }
  const double winch_length = d.properties_.length(d.first_);
  d.properties_ = nominal_;  // same sizes: no new links
  deploy(d, d.first_);
  if (has_winch_) setWinchLinkLength(d, winch_length);
}

void ChainModel::setLinkLength(ChainDeployment& d, int k, double l) const {
  LinkProperties& p = d.properties_;
  // Per unit length, from the configured slot and its section (a cable's mass per length does not
  // change with its length).
  const double per_length = nominal_.mass(k) / nominal_.length(k);
  const double submerged_per_length = nominal_.submerged_mass(k) / nominal_.length(k);
  const double radius = p.radius(k), m = per_length * l;
  p.length(k) = l;
  p.mass(k) = m;
  p.submerged_mass(k) = submerged_per_length * l;
  p.inertia_transverse(k) = m * (l * l / 12.0 + radius * radius / 4.0);
  p.inertia_polar(k) = m * (radius * radius / 2.0);

  LinkConstants& c = d.lanes_[k / kBlockLanes];
  const int i = k % kBlockLanes;
  const bool deployed = l > 0.0;
  // A slot on the drum carries nothing (attachments are refused with a winch; config_loader.cpp).
  const PointSums points = deployed ? points_[k] : PointSums{};
  const double added = deployed ? p.added_mass_per_length(k) : 0.0;
  const double g = p.gravity, rho = fluid_density_;
  c.length[i] = l;
  c.mass_per_length[i] = deployed ? per_length : 0.0;
  c.added[i] = added;
  c.across[i] = c.mass_per_length[i] + added;
  // EA / l and c_a / l of the link's stretch.
  const bool stretches = deployed && axial_ && !(last_locked_ && k == n_ - 1);
  // With a stretch, half of the cable's own mass (and its weight) rides at the far end beyond it, and the
  // link's body keeps the rest with the moments that make the two together the uniform rod at s = 0: mass
  // m/2, first moment 0, second moment m l^2/3 - (m/2) l^2 (docs/MODEL.md section 12). The axial modes
  // are then lumped as a centred scheme lumps them (second order in n), the rotations are unchanged. Not
  // with a winch: its link's mass changes as it pays out, and a far-end point would gain mass at the far
  // end's velocity, which the winch's energy booking does not have (every link's mass at its base end).
  const bool far_point = stretches && far_points_;
  const double far_mass = far_point ? 0.5 * m : 0.0;
  const double far_weight = far_point ? 0.5 * g * p.submerged_mass(k) : 0.0;
  c.far_mass[i] = far_mass;
  c.far_weight[i] = far_weight;
  c.weight[i] = g * (p.submerged_mass(k) + points.sub0) - far_weight;
  c.weight_moment[i] = g * (0.5 * l * p.submerged_mass(k) + points.sub1) - far_weight * l;
  c.translational[i] = l * c.across[i] + points.mass0 + points.added0 - far_mass;
  c.half_moment[i] = 0.5 * l * l * c.across[i] + points.mass1 + points.added1 - far_mass * l;
  c.third_moment[i] = l * l * l / 3.0 * c.across[i] + points.mass2 + points.added2 - far_mass * l * l;
  // The translation integral over the link already holds m l^2/12; the rest of I_T is the thickness.
  c.thick_transverse[i] = m * (radius * radius / 4.0);
  c.own_transverse[i] = c.third_moment[i] + c.thick_transverse[i];
  c.polar[i] = p.inertia_polar(k);
  c.inverse_polar[i] = deployed ? 1.0 / p.inertia_polar(k) : 0.0;
  c.structure0[i] = m + points.mass0 - far_mass;
  c.structure1[i] = 0.5 * l * m + points.mass1 - far_mass * l;
  c.structure2[i] = l * l / 3.0 * m + points.mass2 - far_mass * l * l;
  c.point_added0[i] = points.added0;
  c.point_added1[i] = points.added1;
  c.point_added2[i] = points.added2;
  const DragCoefficients drag =
      deployed ? LinkDrag::coefficients(rho, 2.0 * radius, p.drag_normal(k), p.drag_tangential(k)) : DragCoefficients{};
  c.drag_normal[i] = drag.normal;
  // The skin friction along the link is split with the mass: the far half's on the far-end point at that
  // point's own axial velocity (computeExternalLoads), the body's coefficient halved for the near half. Each
  // stretch then carries the friction beyond its link's middle (second order in n, docs/MODEL.md section 12).
  c.drag_tangential[i] = far_point ? 0.5 * drag.tangential : drag.tangential;
  c.far_tangential[i] = far_point ? 0.5 * drag.tangential * l : 0.0;
  c.axial_stiffness[i] = stretches ? p.axial_stiffness(k) / l : 0.0;
  c.axial_damping[i] = stretches ? p.axial_damping / l : 0.0;
}

void ChainModel::deploy(ChainDeployment& d, int first) const {
  d.first_ = first;
  // A held joint at or before the base link is no longer between two deployed links.
  for (int i = d.hold_count_ - 1; i >= 0; --i) {
    if (d.holds_[i].joint <= first) d.dropHold(i);
  }
  for (int k = 0; k < n_; ++k) setLinkLength(d, k, k < first ? 0.0 : nominal_.length(k));
  // The base's joint (the clamp's springs and dampers, or none for a pin) moves with the base link;
  // the drum's slots have no joints. Every drum slot has the base link's length, so slot 0's configured
  // springs are the clamp's for any slot.
  Eigen::VectorXd LinkProperties::*const springs[] = {
      &LinkProperties::stiffness_elevation, &LinkProperties::stiffness_azimuth, &LinkProperties::stiffness_torsion,
      &LinkProperties::damping_elevation,   &LinkProperties::damping_azimuth,   &LinkProperties::damping_torsion};
  for (Eigen::VectorXd LinkProperties::*v : springs) {
    d.properties_.*v = nominal_.*v;  // same size: no allocation
    (d.properties_.*v).head(first).setZero();
    (d.properties_.*v)(first) = (nominal_.*v)(0);
  }
}

void ChainModel::setWinchLinkLength(ChainDeployment& d, double length) const {
  if (length != d.properties_.length(d.first_)) setLinkLength(d, d.first_, length);
}

}  // namespace cable_dynamics
