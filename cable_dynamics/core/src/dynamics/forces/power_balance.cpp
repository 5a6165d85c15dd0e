#include "cable_dynamics/dynamics/forces/power_balance.h"

#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/joint_torques.h"

namespace cable_dynamics {
namespace {

/// The energy the winch pays out with the cable per metre [J/m]: kinetic energy per length of the
/// material at the base end (translation, and the rotation of the section) plus its potential energy
/// there. The deployed cable's energy grows by this times the pay-out speed, besides the work done on it.
double paidOutEnergyPerLength(const ChainData& data, const Vec3& exit_velocity) {
  const int first = data.deployed.firstLink();
  const LinkConstants& c = data.deployed.of(first);
  const LinkBlock& block = data.links.of(first);
  const int i = LinkBlocks::lane(first);
  const double l = c.length[i], per_length = c.mass_per_length[i];
  const Vec3 omega = block.omega[i];
  const double spin = dot(omega, block.u[i]);
  const double kinetic = 0.5 * per_length * dot(exit_velocity, exit_velocity) +
                         0.5 * (c.thick_transverse[i] * (dot(omega, omega) - spin * spin) + c.polar[i] * spin * spin) / l;
  const double potential = -(c.weight[i] / l) * block.base_pos.z[i];
  return kinetic + potential;
}

}  // namespace

double endsInputPower(const ChainModel& model, const ChainData& data, const EndInputs& ends,
                      const Eigen::Vector3d& base_force) {
  const int first = data.deployed.firstLink();
  const Vec3 exit_velocity = data.links.of(first).base_vel[LinkBlocks::lane(first)];
  double power = base_force.dot(toEigen(exit_velocity)) + data.coupling.dot(data.tip_velocity) +
                 data.clamp_torque.dot(data.clamp_omega) + data.tip_clamp_torque.dot(data.tip_clamp_omega);
  if (ends.winch) {
    power += ends.winch_speed * paidOutEnergyPerLength(data, exit_velocity);
    if (model.axial()) power += winchStrainPower(data, ends.winch_speed);
  }
  if (model.body().active) power += data.body.thrust_power;  // after the solve (finishRovBody)
  return power;
}

double lossPower(const ChainModel& model, const ChainData& data, double added_mass_power, double contact_dissipation,
                 double axial_loss) {
  const double body = model.body().active ? data.body.fluid_power : 0.0;  // after the solve (finishRovBody)
  return data.drag_power + added_mass_power + damperPower(model, data) + jointHoldPower(data) -
         contact_dissipation + body - axial_loss;
}

}  // namespace cable_dynamics
