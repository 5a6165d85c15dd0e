#include "cable_dynamics/dynamics/external_loads.h"

#include <algorithm>
#include <iterator>

#include "cable_dynamics/dynamics/forces/coupling.h"
#include "cable_dynamics/dynamics/forces/point_drag.h"
#include "cable_dynamics/dynamics/hot_path.h"
#include "cable_dynamics/dynamics/seabed_contact.h"

namespace cable_dynamics {
namespace {

/// The far half's skin friction (LinkConstants::far_tangential) on each far-end point of a block's `lanes`
/// links, at the point's own velocity along the link, u . v_base + s' (u . u' = 0), and the current at its
/// depth: LinkBlock::far_drag, and its power added to the drag's.
EIGEN_ALWAYS_INLINE void addFarSkinFriction(const CurrentField& field, const LinkConstants& constants, LinkBlock& block,
                                            int lanes) {
  double flow[kBlockLanes];  // the current along u at each far-end point [m/s]; 0 in the padding lanes
  if (field.uniform()) {
    const Vec3 current = toVec3(field.uniformValue());
    for (int i = 0; i < kBlockLanes; ++i) flow[i] = dot(block.u[i], current);
  } else {
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 u = block.u[i];
      const double depth = block.base_pos.z[i] + (constants.length[i] + block.stretch[i]) * u.z;
      flow[i] = i < lanes ? dot(u, toVec3(field.at(depth))) : 0.0;
    }
  }
  CABLE_LANE_LOOP
  for (int i = 0; i < kBlockLanes; ++i) {
    const double speed = dot(block.u[i], block.base_vel[i]) + block.stretch_rate[i];  // the point's, along u
    const double along = flow[i] - speed;
    const double far = constants.far_tangential[i] * std::abs(along) * along;
    block.far_drag[i] = far;
    block.drag_power[i] += far * speed;
  }
}

}  // namespace

CABLE_HOT_PATH void computeExternalLoads(const ChainModel& model, ChainData& data, const EndInputs& ends) {
  const int n = model.links();
  const CurrentField& current_field = data.current;
  const bool in_water = model.fluidDensity() > 0.0;
  const bool uniform = current_field.uniform();
  const Vec3 current = toVec3(current_field.uniformValue());
  const bool far_points = model.farEndPoints();
  double drag_power = 0.0;
  for (int b = data.deployed.firstBlock(); b < data.links.blocks(); ++b) {
    const LinkConstants& constants = data.deployed.block(b);
    LinkBlock& block = data.links.block(b);
    // Submerged weight, uniform along the link, and the attachments' at their points: total and first
    // moment about the base end.
    CABLE_LANE_LOOP
    for (int i = 0; i < kBlockLanes; ++i) {
      block.force.set(i, {0.0, 0.0, constants.weight[i]});
      block.moment.set(i, {0.0, 0.0, constants.weight_moment[i]});
    }
    if (!in_water) {
      if (far_points) std::fill(std::begin(block.far_drag), std::end(block.far_drag), 0.0);
      continue;
    }
    if (uniform) {
      model.drag().addUniform(current, constants, block);
    } else {
      const int first = b * kBlockLanes, count = std::min(kBlockLanes, n - first);
      for (int i = 0; i < count; ++i) {
        Eigen::Vector3d fd, md;
        model.drag().pointwise(current_field, constants.length[i], {constants.drag_normal[i], constants.drag_tangential[i]},
                               toEigen(block.base_pos[i]),
                               toEigen(block.base_vel[i]), toEigen(block.u[i]), toEigen(block.axis_rate[i]), fd, md);
        block.force.set(i, block.force[i] + toVec3(fd));
        block.moment.set(i, block.moment[i] + toVec3(md));
        block.drag_power[i] = fd.dot(toEigen(block.base_vel[i])) + md.dot(toEigen(block.axis_rate[i]));
      }
    }
    if (far_points) addFarSkinFriction(current_field, constants, block, std::min(kBlockLanes, n - b * kBlockLanes));
    double power = 0.0;  // the padding lanes' drag is zero (zero length)
    for (int i = 0; i < kBlockLanes; ++i) power += block.drag_power[i];
    drag_power += power;
  }
  // The attachments' drag, at each one's point with that point's velocity (few: a loop of its own).
  if (model.attachmentDrag()) {
    for (const LinkAttachment& a : model.attachments()) {
      if (a.drag_area <= 0.0) continue;
      LinkBlock& block = data.links.of(a.link);
      const int i = LinkBlocks::lane(a.link);
      const Eigen::Vector3d u = toEigen(block.u[i]), rate = toEigen(block.axis_rate[i]);
      const Eigen::Vector3d position = toEigen(block.base_pos[i]) + a.offset * u;
      const Eigen::Vector3d velocity = toEigen(block.base_vel[i]) + a.offset * rate;
      const Eigen::Vector3d drag = pointDrag(model.fluidDensity(), a.drag_area, velocity, current_field.at(position.z()));
      block.force.set(i, block.force[i] + toVec3(drag));
      block.moment.set(i, block.moment[i] + toVec3(a.offset * drag));
      drag_power += pointDragPower(drag, velocity);
    }
  }
  // The load: weight, drag, and the PD coupling to its anchor or to the ROV.
  const LoadConstants& load = model.load();
  data.load_external = load.weight * Eigen::Vector3d::UnitZ();
  if (in_water && load.drag_area > 0.0) {
    const Eigen::Vector3d drag =
        pointDrag(model.fluidDensity(), load.drag_area, data.tip_velocity, current_field.at(data.tip_position.z()));
    data.load_external += drag;
    drag_power += pointDragPower(drag, data.tip_velocity);
  }
  data.drag_power = drag_power;
  data.coupling.setZero();
  if (ends.load_coupled && model.heldTip()) {
    // An exact anchor: no spring; the recursion solves for the force that gives the tip this acceleration.
    // Its drift correction (Baumgarte's, critically damped at tau, the step) brings back the round-off and
    // the integrator's truncation error, which an acceleration-level hold alone would let accumulate.
    const double rate = 1.0 / model.holdTimeConstant();
    data.tip_demand = ends.target_acceleration - 2.0 * rate * (data.tip_velocity - ends.target_velocity) -
                      rate * rate * (data.tip_position - ends.target_position);
  } else if (ends.load_coupled) {
    data.coupling = load.coupling().force(data.tip_position, data.tip_velocity,
                                          ends.target_position + ends.coupling_rest_shift,
                                          ends.target_velocity + ends.coupling_rest_shift_rate);
    data.load_external += data.coupling;
  }
  data.contact_dissipation = 0.0;
  if (model.seabedContact().enabled()) addSeabedContact(model, data);  // after the coupling: it adds to load_external
}

}  // namespace cable_dynamics
