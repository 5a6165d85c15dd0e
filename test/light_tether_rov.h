#pragma once
/// \file
/// \brief A BlueROV2-class ROV body on a light tether (tests of the body under every scheme): an 11.5 kg ROV
///        on 16 m of 8 links of a 10 mm tether, EI 0.5 N m^2, in a 0.3 m/s current, holding station,
///        started 0.3 rad off the vertical. A config without its simulation section.

namespace cable_dynamics_test {

inline constexpr const char* kLightTetherRov = R"(
cable: {links: 8, length: 16.0, diameter: 0.01, mass_per_length: 0.1, stiffness: {model: bending, bending_rigidity: 0.5}}
load: {mass: 11.5, volume: 0.0114, mode: body, attachment: [-0.2, 0.0, 0.1],
       body: {inertia: [0.16, 0.16, 0.16], added_mass: [5.5, 12.7, 14.57, 0.12, 0.12, 0.12],
              linear_damping: [4.0, 6.2, 5.2, 0.07, 0.07, 0.07], quadratic_damping: [18.0, 21.7, 37.0, 1.5, 1.5, 1.5],
              center_of_buoyancy: [0.0, 0.0, 0.02],
              station_keeping: {position_gain: [17, 25, 26], velocity_gain: [34, 50, 52], attitude_gain: [0, 0, 0.3],
                                rate_gain: [0, 0, 0.5], max_force: 90.0, max_torque: 10.0}}}
fluid: {density: 1025.0, current: [0.3, 0.1, 0.0]}
initial: {elevation: 0.3}
)";

}  // namespace cable_dynamics_test
