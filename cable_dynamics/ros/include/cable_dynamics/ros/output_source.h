#pragma once
/// \file
/// \brief What the node publishes about one instant, read from the simulator: the snapshot (link frames
///        included) and the winch's state. Checked finite as a whole.

#include <Eigen/Core>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// What the node reports of the winch besides the snapshot's deployed length, speed and line pull.
struct WinchReading {
  bool present = false;          ///< a winch is configured
  bool targeting = false;        ///< driving to target_length (else running at commanded_speed)
  double commanded_speed = 0.0;  ///< the speed command, + paying out [m/s]
  double target_length = 0.0;    ///< the length command [m] (when targeting)
  long links_added = 0;          ///< since reset
  long links_removed = 0;        ///< since reset
};

/// The published instant, sized once for n links and refilled every cycle without allocating.
struct OutputSource {
  SimulationSnapshot snapshot;
  WinchReading winch;
  Eigen::VectorXd spring_force;      ///< (3n) dV/dq of the joint springs (dampers excluded), the snapshot's; JointState effort = -this [N m]
};

/// Fills `out` from the simulator's present state. Returns false when the state cannot be evaluated or
/// any number of it is not finite: then nothing of it may be published.
bool readOutputs(CableSimulator& sim, OutputSource& out);

}  // namespace cable_dynamics
