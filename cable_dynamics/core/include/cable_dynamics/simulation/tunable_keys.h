#pragma once
/// \file
/// \brief The config keys live tuning may change on a running simulator (CableSimulator::retune), listed
///        once. The node's tuning table (ros/tuning_checks.h) names its coefficients by these keys, and
///        test_tuning checks that table and cfg/Tuning.cfg against this one.

#include <array>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// A tunable coefficient: its config key and where the parsed parameters hold it.
struct TunableKey {
  const char* key;                           ///< e.g. "fluid.drag_normal"
  double& (*in)(CableParams&);               ///< its value in the parameters
  double& (*in_section)(SectionParams&);     ///< a section's own value the key is the default of, or nullptr
};

/// Fluid coefficients (sections without their own value take the cable's) and the load coupling's gains:
/// none of them stores energy, so a running simulator takes them between two steps.
extern const std::array<TunableKey, 5> kTunableKeys;

}  // namespace cable_dynamics
