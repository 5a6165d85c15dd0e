#include "cable_dynamics/dynamics/seabed_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/hot_path.h"

namespace cable_dynamics {
namespace {

/// The default stiffness rests the heaviest section (and the load) at 1/kRestingShare of the allowed
/// penetration, and leaves the rest for landing: a point arriving at v stops within v sqrt(m / k), about
/// v / (10 sqrt(g' / penetration)) (in water 1 m/s lands within half of a 0.02 m allowance).
constexpr double kRestingShare = 100.0;

/// Whether a point in contact is held by its anchor: the friction's argument below breakout (|w| < 1).
bool stuck(const ContactLaw& law, const ContactPlace& place, const Vec3& v) {
  const Vec3 slip = v - dot(v, place.normal) * place.normal;
  const Vec3 w = frictionArgument(law, place, slip);
  return dot(w, w) < 1.0;
}

/// Puts the anchor `anchor` (3 values) on `point` [m].
void anchorAt(const Vec3& point, double* anchor) {
  anchor[0] = point.x;
  anchor[1] = point.y;
  anchor[2] = point.z;
}

/// The anchor `anchor` [m] of a point at `point` [m] on the bed (inward normal `normal`) after a step:
/// where it was if the point's offset along the bed is within `reach` [m], else `reach` behind the point
/// along that offset (the slip the Coulomb law allowed).
void slideAnchor(const Vec3& point, const Vec3& normal, double reach, double* anchor) {
  const Vec3 offset = ContactAnchors::offset(anchor, 0, point);
  const Vec3 along = offset - dot(offset, normal) * normal;
  const double distance = std::sqrt(dot(along, along));
  if (distance > reach) anchorAt(point - (reach / distance) * along, anchor);
}

}  // namespace

SeabedContactConstants makeSeabedContact(const CableParams& params, const LinkProperties& p) {
  SeabedContactConstants c;
  const SeabedParams& s = params.seabed;
  c.bed = Seabed(s);
  if (!s.enabled) return c;
  c.points = s.contact_points;
  for (int j = 0; j < c.points; ++j) c.node[j] = (j + 0.5) / c.points;
  // The heaviest submerged weight per length among the slots (a float's buoyancy is its own; a cable
  // that floats everywhere is pressed down only by its tension: its own weight in air sets the scale).
  double heaviest = 0.0;
  for (int k = 0; k < p.n; ++k) {
    if (p.length(k) > 0.0) heaviest = std::max(heaviest, p.gravity * p.submerged_mass(k) / p.length(k));
  }
  if (heaviest <= 0.0) heaviest = p.gravity * params.mass_per_length;
  c.allowed_penetration = s.penetration;
  c.stiffness = s.stiffness > 0.0 ? s.stiffness : kRestingShare * heaviest / s.penetration;
  c.rest_penetration = std::max(heaviest / c.stiffness, 1e-6 * s.penetration);
  c.friction_axial = s.friction_axial;
  c.friction_lateral = s.friction_lateral;
  c.friction_velocity = s.friction_velocity;
  c.friction_breakout = s.friction_breakout;
  c.damping.assign(p.n, 0.0);
  for (int k = 0; k < p.n; ++k) {
    const double per_length = p.length(k) > 0.0 ? p.mass(k) / p.length(k) : params.mass_per_length;
    c.damping[k] = 2.0 * s.damping_ratio * std::sqrt(c.stiffness * (per_length + p.added_mass_per_length(k)));
  }
  const double load_weight = p.gravity * p.load_submerged_mass;
  // An exact anchor holds the load where it is whatever the bed does (the bed's push would only move the
  // anchor's reaction by it), and in the statics a load resting on the bed fought the anchor's hold: a
  // light line anchored on the bottom stalled there (bench/seabed_step). A spring anchor gives: the bed
  // holds its load too.
  c.load_contact = (params.load.mode == LoadMode::kFree ||
                    (params.load.mode == LoadMode::kAnchored && !params.load.heldExactly())) &&
                   load_weight > 0.0;
  if (c.load_contact) {
    c.load_stiffness = kRestingShare * load_weight / s.penetration;
    c.load_damping = 2.0 * s.damping_ratio * std::sqrt(c.load_stiffness * (p.load_mass + params.load.added_mass));
    c.load_rest = load_weight / c.load_stiffness;
  }
  return c;
}

namespace {

/// The K points of one link on a flat bed (normal +z everywhere): the same law (forces/contact.h), with what
/// the points share found once, the axis's direction along the bed, and no probe. Adds the force and its
/// first moment, returns the dissipated power [W]. The hot path's case.
/// (Its own clones, called from its caller's: GCC cannot inline a target_clones function, and ignored the
/// always_inline this once had.)
CABLE_HOT_PATH double flatLinkContact(const SeabedContactConstants& c, const ContactLaw& law, double l, const Vec3& base,
                                      const Vec3& velocity, const Vec3& axis, const Vec3& rate, const double* anchors,
                                      Vec3& force, Vec3& moment) {
  const double depth = c.bed.shallowest();
  ContactPlace place;
  place.has_along = alongTheBed(axis, place.normal, place.along);
  double dissipation = 0.0;
  for (int j = 0; j < c.points; ++j) {
    const double s = c.node[j] * l;
    place.delta = base.z + s * axis.z - depth;
    if (place.delta <= 0.0) continue;
    if (anchors) place.offset = ContactAnchors::offset(anchors, j, base + s * axis);
    PointContact contact;
    contactForce(law, place, velocity + s * rate, contact);
    force = force + contact.force;
    moment = moment + s * contact.force;
    dissipation += contact.dissipation;
  }
  return dissipation;
}

/// The contact of every deployed link and of the load at the kinematics in `data`, each point's velocity
/// shifted by `shift` when given. Adds the forces to `links` and `load_external` when given (the hot path:
/// the data's own), fills `report` when given. Returns the dissipated power [W].
CABLE_HOT_PATH double contactPass(const ChainModel& model, const ChainData& data, LinkBlocks* links,
                                  Eigen::Vector3d* load_external, SeabedReport* report,
                                  const ContactVelocityShift* shift = nullptr) {
  const SeabedContactConstants& c = model.seabedContact();
  const int n = model.links(), first = data.deployed.firstLink();
  double dissipation = 0.0, arc_before = 0.0;
  const double shallowest = c.bed.shallowest();
  const bool flat_kernel = c.bed.flat() && report == nullptr;  // the hot path on a flat bed
  // The report's touchdown: where the signed penetration first crosses zero from the base, linear
  // between the contact point before (or the base end) and the first one in the bed.
  double previous_arc = 0.0, previous_penetration = -std::numeric_limits<double>::infinity();
  for (int b = data.deployed.firstBlock(); b < data.links.blocks(); ++b) {
    const LinkConstants& constants = data.deployed.block(b);
    const LinkBlock& block = data.links.block(b);
    // Nothing of a block whose links all end above the shallowest depth touches: one test for eight.
    double deepest = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < kBlockLanes; ++i) {
      const double z0 = block.base_pos.z[i], z1 = z0 + constants.length[i] * block.u.z[i];
      deepest = std::max(deepest, std::max(z0, z1));
    }
    if (deepest <= shallowest && !report) continue;  // (the arc lengths only matter to the report)
    for (int i = 0; i < kBlockLanes; ++i) {
      const int k = b * kBlockLanes + i;
      const double l = constants.length[i];
      if (k < first || k >= n || l <= 0.0) continue;
      const double share = l / c.points;
      const ContactLaw law = c.linkLaw(k, share);
      const Vec3 base = block.base_pos[i], axis = block.u[i];
      Vec3 velocity = block.base_vel[i], rate = block.axis_rate[i];
      if (shift) {
        velocity = velocity + toVec3(shift->base->col(k));
        rate = rate + cross(toVec3(shift->omega->col(k)), axis);
      }
      Vec3 force{0.0, 0.0, 0.0}, moment{0.0, 0.0, 0.0};
      const double* anchors = data.anchors.of(k);
      if (flat_kernel) {
        dissipation += flatLinkContact(c, law, l, base, velocity, axis, rate, anchors, force, moment);
        if (!links) continue;
        LinkBlock& target = links->block(b);
        target.force.set(i, target.force[i] + force);
        target.moment.set(i, target.moment[i] + moment);
        continue;
      }
      double normal = 0.0;
      for (int j = 0; j < c.points; ++j) {
        const double s = c.node[j] * l;
        const Vec3 point = base + s * axis;
        ContactPlace place;
        PointContact contact;
        const bool touching = contactPlace(c.bed, point, axis, place);
        if (touching && anchors) place.offset = ContactAnchors::offset(anchors, j, point);
        if (touching) contactForce(law, place, velocity + s * rate, contact);
        if (report && !report->touching) {
          const double penetration = touching ? place.delta : Seabed::penetration(c.bed.probe(point.x, point.y), point.z);
          if (touching) {
            const double before = std::isfinite(previous_penetration) ? previous_penetration : penetration;
            const double fraction = before < 0.0 ? -before / (penetration - before) : 0.0;
            report->touchdown_arc_length = previous_arc + fraction * (arc_before + s - previous_arc);
            const Eigen::Vector3d here = toEigen(point);
            report->touchdown = here + (fraction - 1.0) * (arc_before + s - previous_arc) * toEigen(axis);
          }
          previous_arc = arc_before + s;
          previous_penetration = penetration;
        }
        if (!touching) continue;
        force = force + contact.force;
        moment = moment + s * contact.force;
        dissipation += contact.dissipation;
        if (report) {
          normal -= dot(contact.force, place.normal);  // the friction is tangential
          report->grounded_length += share;
          if (anchors && stuck(law, place, velocity + s * rate)) report->stuck_length += share;
          report->max_penetration = std::max(report->max_penetration, contact.penetration);
          report->touching = true;
        }
      }
      if (links) {
        LinkBlock& target = links->block(b);
        target.force.set(i, target.force[i] + force);
        target.moment.set(i, target.moment[i] + moment);
      }
      if (report) {
        report->link_force.col(k) = toEigen(force);
        report->normal_force(k) = normal;
      }
      arc_before += l;
    }
  }
  if (c.load_contact) {
    ContactPlace place;
    PointContact contact;
    if (contactPlace(c.bed, toVec3(data.tip_position), {0.0, 0.0, 0.0}, place)) {
      place.offset = data.anchors.loadOffset(data.tip_position);
      const Eigen::Vector3d velocity = shift ? Eigen::Vector3d(data.tip_velocity + shift->tip) : data.tip_velocity;
      contactForce(c.loadLaw(), place, toVec3(velocity), contact);
      if (load_external) *load_external += toEigen(contact.force);
      dissipation += contact.dissipation;
      if (report) {
        report->load_force = toEigen(contact.force);
        report->max_penetration = std::max(report->max_penetration, contact.penetration);
      }
    }
  }
  return dissipation;
}

}  // namespace

CABLE_HOT_PATH void addSeabedContact(const ChainModel& model, ChainData& data) {
  data.contact_dissipation = contactPass(model, data, &data.links, &data.load_external, nullptr);
}

void placeContactAnchors(const ChainModel& model, ChainData& data, bool slide, int winch_links) {
  if (!data.anchors.active()) return;
  const SeabedContactConstants& c = model.seabedContact();
  const int n = model.links(), first = data.deployed.firstLink();
  for (int k = 0; k < n; ++k) {
    const double l = data.deployed.get(&LinkConstants::length, k);
    const Eigen::Vector3d base = data.links.get(&LinkBlock::base_pos, k), u = data.links.get(&LinkBlock::u, k);
    // A link on the drum or wholly above the bed: no anchor (nothing to hold; one that touches down within
    // the next step is held from where it touched at the step after).
    const bool was_placed = data.anchors.placed[k];
    data.anchors.placed[k] = k >= first && l > 0.0 && std::max(base.z(), base.z() + l * u.z()) > c.bed.shallowest();
    if (!data.anchors.placed[k]) continue;
    // The winch's link: its points move along the cable as it is paid out, so its anchors stay on them.
    const bool holds = slide && was_placed && !(model.hasWinch() && k < first + winch_links);
    for (int j = 0; j < c.points; ++j) {
      const Vec3 point = toVec3(Eigen::Vector3d(base + (c.node[j] * l) * u));
      double* anchor = data.anchors.link.col(k * c.points + j).data();
      ContactPlace place;
      if (holds && contactPlace(c.bed, point, toVec3(u), place)) {
        slideAnchor(point, place.normal, c.friction_breakout, anchor);
      } else {
        anchorAt(point, anchor);  // off the bed (or a new state): the anchor goes with the point
      }
    }
  }
  if (c.load_contact) {
    const Vec3 point = toVec3(data.tip_position);
    ContactPlace place;
    if (slide && contactPlace(c.bed, point, {0.0, 0.0, 0.0}, place)) {
      slideAnchor(point, place.normal, c.friction_breakout, data.anchors.load.data());
    } else {
      data.anchors.load = data.tip_position;
    }
  }
}

CABLE_HOT_PATH double seabedContactDissipation(const ChainModel& model, const ChainData& data,
                                              const ContactVelocityShift& shift) {
  if (!model.seabedContact().enabled()) return 0.0;
  return contactPass(model, data, nullptr, nullptr, nullptr, &shift);
}

void reportSeabedContact(const ChainModel& model, const ChainData& data, SeabedReport& report) {
  const int n = model.links();
  // Reset in place: the arrays keep their storage from the last report (one allocation, at the first).
  report.link_force.setZero(3, n);
  report.normal_force.setZero(n);
  report.load_force.setZero();
  report.grounded_length = 0.0;
  report.touching = false;
  report.touchdown_arc_length = 0.0;
  report.touchdown.setZero();
  report.max_penetration = 0.0;
  report.stuck_length = 0.0;
  contactPass(model, data, nullptr, nullptr, &report);
  report.energy = seabedContactEnergy(model, data);
}

CABLE_HOT_PATH double seabedContactEnergy(const ChainModel& model, const ChainData& data) {
  const SeabedContactConstants& c = model.seabedContact();
  if (!c.enabled()) return 0.0;
  const int n = model.links();
  double energy = 0.0;
  for (int k = data.deployed.firstLink(); k < n; ++k) {
    const double l = data.deployed.get(&LinkConstants::length, k);
    if (l <= 0.0) continue;
    const Eigen::Vector3d base = data.links.get(&LinkBlock::base_pos, k), axis = data.links.get(&LinkBlock::u, k);
    if (std::max(base.z(), base.z() + l * axis.z()) <= c.bed.shallowest()) continue;
    const ContactLaw law = c.linkLaw(k, l / c.points);
    for (int j = 0; j < c.points; ++j) {
      // On a flat bed the penetration is linear along the link: no probe.
      const Eigen::Vector3d p = base + (c.node[j] * l) * axis;
      const double delta = c.bed.flat() ? base.z() + c.node[j] * l * axis.z() - c.bed.shallowest()
                                        : Seabed::penetration(c.bed.probe(p.x(), p.y()), p.z());
      if (delta > 0.0) energy += contactEnergy(law, delta);
    }
  }
  if (c.load_contact) {
    const Eigen::Vector3d& p = data.tip_position;
    const double delta = Seabed::penetration(c.bed.probe(p.x(), p.y()), p.z());
    if (delta > 0.0) energy += contactEnergy(c.loadLaw(), delta);
  }
  return energy;
}

}  // namespace cable_dynamics
