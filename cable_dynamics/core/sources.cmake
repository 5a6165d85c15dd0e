# The ROS-free core's sources, listed once: the package (CMakeLists.txt), its no-allocation test build
# (test/tests.cmake) and the benchmark (bench/CMakeLists.txt) all build them from this list.
# Eigen, yaml-cpp and the standard library only.
set(CABLE_CORE_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CABLE_CORE_INCLUDE_DIR ${CABLE_CORE_DIR}/include)
set(CABLE_CORE_SOURCES
  # params: parameters, each key's range, the config loader, the input gate, initial states
  ${CABLE_CORE_DIR}/src/params/cable_params.cpp
  ${CABLE_CORE_DIR}/src/params/key_ranges.cpp
  ${CABLE_CORE_DIR}/src/params/config_section.cpp
  ${CABLE_CORE_DIR}/src/params/range_gate.cpp
  ${CABLE_CORE_DIR}/src/params/config_loader.cpp
  ${CABLE_CORE_DIR}/src/params/input_gate.cpp
  ${CABLE_CORE_DIR}/src/params/seabed_config.cpp
  ${CABLE_CORE_DIR}/src/params/states.cpp
  # dynamics: the paper's model, the joint springs, the fluid, the chain's equations of motion (the
  # model/data split, then one file per pass, then the facade that runs them in order)
  ${CABLE_CORE_DIR}/src/dynamics/azimuth_tracker.cpp
  ${CABLE_CORE_DIR}/src/dynamics/paper_model.cpp
  ${CABLE_CORE_DIR}/src/dynamics/elastic_joints.cpp
  ${CABLE_CORE_DIR}/src/dynamics/fluid.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_deployment.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_model.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_data.cpp
  ${CABLE_CORE_DIR}/src/dynamics/paper_coordinates.cpp
  ${CABLE_CORE_DIR}/src/dynamics/kinematics.cpp
  ${CABLE_CORE_DIR}/src/dynamics/seabed.cpp
  ${CABLE_CORE_DIR}/src/dynamics/seabed_contact.cpp
  ${CABLE_CORE_DIR}/src/dynamics/external_loads.cpp
  ${CABLE_CORE_DIR}/src/dynamics/joint_torques.cpp
  ${CABLE_CORE_DIR}/src/dynamics/energies.cpp
  ${CABLE_CORE_DIR}/src/dynamics/articulated_body.cpp
  ${CABLE_CORE_DIR}/src/dynamics/dense_solver.cpp
  ${CABLE_CORE_DIR}/src/dynamics/cable_limits.cpp
  ${CABLE_CORE_DIR}/src/dynamics/rov_body.cpp
  ${CABLE_CORE_DIR}/src/dynamics/stiff_articulated_body.cpp
  # dynamics/forces: each force's value, power, Jacobian and form at rest (most are header-only), and the
  # energy balance's power sums
  ${CABLE_CORE_DIR}/src/dynamics/forces/axial_spring.cpp
  ${CABLE_CORE_DIR}/src/dynamics/forces/power_balance.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_dynamics.cpp
  # simulation: time schemes, the winch, end conditions, the step check, the simulator, link frames
  ${CABLE_CORE_DIR}/src/simulation/time_schemes/time_scheme.cpp
  ${CABLE_CORE_DIR}/src/simulation/time_schemes/rk4.cpp
  ${CABLE_CORE_DIR}/src/simulation/time_schemes/semi_implicit.cpp
  ${CABLE_CORE_DIR}/src/simulation/time_schemes/linear_implicit.cpp
  ${CABLE_CORE_DIR}/src/simulation/body_motion.cpp
  ${CABLE_CORE_DIR}/src/simulation/station_keeper.cpp
  ${CABLE_CORE_DIR}/src/simulation/winch.cpp
  ${CABLE_CORE_DIR}/src/simulation/winch_links.cpp
  ${CABLE_CORE_DIR}/src/simulation/end_conditions.cpp
  ${CABLE_CORE_DIR}/src/simulation/step_check.cpp
  ${CABLE_CORE_DIR}/src/simulation/stable_step.cpp
  ${CABLE_CORE_DIR}/src/simulation/cable_simulator.cpp
  ${CABLE_CORE_DIR}/src/simulation/tuning.cpp
  ${CABLE_CORE_DIR}/src/simulation/link_frames.cpp
  # statics: the equilibrium shape (the equations link by link, the starting guesses, Newton)
  ${CABLE_CORE_DIR}/src/statics/static_equations.cpp
  ${CABLE_CORE_DIR}/src/statics/static_start.cpp
  ${CABLE_CORE_DIR}/src/statics/catenary_start.cpp
  ${CABLE_CORE_DIR}/src/statics/static_newton.cpp
  ${CABLE_CORE_DIR}/src/statics/static_solver.cpp
)
