#pragma once
/// \file
/// \brief One cycle's stepping: as many steps as are due, bounded by a count and by wall time; a step that
///        diverges is counted, the simulator recovered (time and inputs carry on), and the cycle ends.

#include <string>

#include <ros/time.h>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// What one cycle of stepping did.
struct CycleReport {
  long steps = 0;            ///< steps taken (accepted)
  long retried = 0;          ///< of them, steps that needed substeps (StepReport.substeps > 1)
  bool diverged = false;     ///< a step failed even in substeps: the simulator was recovered
  bool out_of_time = false;  ///< stopped at the wall-time deadline with steps still due
  std::string message;       ///< why the step diverged (empty otherwise)
};

/// Takes up to `wanted` steps of `sim`, stopping at `deadline` (wall time, read every few steps). After a
/// failed step calls sim.recover() and stops, so nothing from the failed state is ever published.
CycleReport stepCycle(CableSimulator& sim, long wanted, const ros::WallTime& deadline);

}  // namespace cable_dynamics
