#include "cable_dynamics/dynamics/energies.h"

#include "cable_dynamics/dynamics/hot_path.h"

namespace cable_dynamics {

CABLE_HOT_PATH void kineticAndPotentialEnergy(const ChainModel& model, const ChainData& data, double& kinetic,
                                              double& potential) {
  // Translation integrated along each link, rotation of the link's thickness, the load. Per-lane sums
  // (the padding lanes add zero: no mass, no weight), so that the loop runs on vectors.
  double kinetic_lanes[kBlockLanes] = {}, potential_lanes[kBlockLanes] = {};
  for (int b = data.deployed.firstBlock(); b < data.links.blocks(); ++b) {
    const LinkConstants& constants = data.deployed.block(b);
    const LinkBlock& block = data.links.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      // A point at s moves at v + s u': the mass moments (cable and attachments) about the base end
      // give 1/2 (M0 |v|^2 + 2 M1 v.u' + M2 |u'|^2).
      const Vec3 v = block.base_vel[i], c = block.axis_rate[i], omega = block.omega[i], axis = block.u[i];
      const double spin = dot(omega, axis);
      kinetic_lanes[i] += 0.5 * (constants.structure0[i] * dot(v, v) + 2.0 * constants.structure1[i] * dot(v, c) +
                                 constants.structure2[i] * dot(c, c)) +
                          0.5 * constants.thick_transverse[i] * (dot(omega, omega) - spin * spin) +
                          0.5 * constants.polar[i] * spin * spin;
      potential_lanes[i] -= constants.weight[i] * block.base_pos.z[i] + constants.weight_moment[i] * axis.z;
    }
  }
  // With axial elasticity, each link's far-end point beyond its stretch (LinkConstants::far_mass), at l + s
  // along u; rigid links and a winch's have none, and their energy check skips the pass.
  for (int b = data.deployed.firstBlock(); model.farEndPoints() && b < data.links.blocks(); ++b) {
    const LinkConstants& constants = data.deployed.block(b);
    const LinkBlock& block = data.links.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 axis = block.u[i];
      const double lever = constants.length[i] + block.stretch[i];
      const Vec3 far_vel = block.base_vel[i] + lever * block.axis_rate[i] + block.stretch_rate[i] * axis;
      kinetic_lanes[i] += 0.5 * constants.far_mass[i] * dot(far_vel, far_vel);
      potential_lanes[i] -= constants.far_weight[i] * (block.base_pos.z[i] + lever * axis.z);
    }
  }
  kinetic = 0.5 * model.load().mass * data.tip_velocity.squaredNorm();
  potential = -model.load().weight * data.tip_position.z();
  if (model.body().active) {  // its terms are the present state's (ChainDynamics evaluates them with the kinematics)
    double body_kinetic = 0.0, body_potential = 0.0;
    rovBodyEnergy(model.body(), data.body, data.tip_position, body_kinetic, body_potential);
    kinetic += body_kinetic;
    potential += body_potential;
  }
  for (int i = 0; i < kBlockLanes; ++i) {
    kinetic += kinetic_lanes[i];
    potential += potential_lanes[i];
  }
}

}  // namespace cable_dynamics
