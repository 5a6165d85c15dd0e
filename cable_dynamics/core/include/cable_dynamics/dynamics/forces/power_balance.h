#pragma once
/// \file
/// \brief The energy balance's two power sums, written once for every scheme: what the ends put into the
///        cable (the work input's rate) and what the non-conservative forces take out (the dissipated
///        energy's rate). The explicit evaluation (ChainDynamics), the implicit step's stages and the
///        semi-implicit step all call these; each force's own power comes from its module
///        (dynamics/forces/*.h) or the pass that applies it.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// The power the ends put into the cable at the kinematics in `data` [W]: the base's force on the base
/// link's end, `base_force` [N], at that end's material velocity (with a winch, the paid-out cable's),
/// the load coupling at the tip's velocity, the turning clamps' torques at their angular velocities
/// (data.clamp_torque, data.tip_clamp_torque: from the joint springs' pass), and with a winch the energy
/// the paid-out cable brings (its energy per metre at the exit times the pay-out speed). Each scheme passes
/// the base force of its own solve.
double endsInputPower(const ChainModel& model, const ChainData& data, const EndInputs& ends,
                      const Eigen::Vector3d& base_force);

/// The power of the forces that take energy out, at the kinematics and loads in `data` [W] (<= 0 for a
/// physical state): the drag (data.drag_power), the fluid's added mass at the scheme's own accelerations
/// (`added_mass_power`), the joint dampers and the seabed's dampers and friction (`contact_dissipation`
/// [W], >= 0: data.contact_dissipation at the evaluated velocities, or the implicit step's at the
/// velocities its stage solved the dampers at, seabedContactDissipation), and the stretches' dampers
/// (`axial_loss` [W]: axialLoss, or the implicit step's axialLossAtShiftedRates). The dissipated energy
/// grows at minus this.
double lossPower(const ChainModel& model, const ChainData& data, double added_mass_power, double contact_dissipation,
                 double axial_loss);

}  // namespace cable_dynamics
