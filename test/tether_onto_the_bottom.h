#pragma once
/// \file
/// \brief The winch case of test_seabed and test_fold_stop, written once: a 12 m tether in water hanging
///        onto the bottom 10 m below the winch, with a current along x; the winch pays out 8 m from t = 0
///        and hauls it back in from t = 25 s. RK4 at 1 ms unless `overrides` say otherwise.

#include <string>
#include <vector>

#include "cable_dynamics/params/config_loader.h"

namespace cable_dynamics {

/// With bend and twist rigidities EI and GJ [N m^2] (EI 0: a limp tether).
inline CableParams tetherOntoTheBottom(double bending_rigidity, double torsional_rigidity,
                                       const std::vector<std::string>& overrides) {
  return loadConfigString(
      "cable: {links: 12, length: 12.0, diameter: 0.02, mass_per_length: 0.8,\n"
      "        stiffness: {model: bending, bending_rigidity: " + std::to_string(bending_rigidity) +
          ", torsional_rigidity: " + std::to_string(torsional_rigidity) + "}}\n"
          "fluid: {current: [0.3, 0.0, 0.0]}\n"
          "seabed: {depth: 10.0, friction: {axial: 0.3, lateral: 0.6}}\n"
          "initial: {mode: equilibrium}\n"
          "winch: {max_length: 24.0, min_length: 6.0, max_speed: 0.5, max_acceleration: 0.5, schedule: "
          "[{time: 0.0, speed: 0.4}, {time: 20.0, speed: 0.0}, {time: 25.0, speed: -0.4}, {time: 45.0, speed: 0.0}]}\n"
          "simulation: {dt: 0.001}\n",
      overrides);
}

}  // namespace cable_dynamics
