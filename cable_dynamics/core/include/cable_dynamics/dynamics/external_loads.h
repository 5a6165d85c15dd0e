#pragma once
/// \file
/// \brief The loads on the chain that do not come from its joints: submerged weight, Morison drag in the
///        current, the seabed's contact, and on the load its weight, drag, seabed contact and the PD
///        coupling to its anchor or to the ROV.

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// Fills each link's force, first moment and drag power, data.drag_power, data.load_external,
/// data.coupling and data.contact_dissipation, after computeKinematics(). O(n).
void computeExternalLoads(const ChainModel& model, ChainData& data, const EndInputs& ends);

}  // namespace cable_dynamics
