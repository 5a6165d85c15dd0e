# The ROS-free core's sources, listed once: the package (CMakeLists.txt), its no-allocation test build
# (test/tests.cmake) and the benchmark (bench/CMakeLists.txt) all build them from this list.
# Eigen, yaml-cpp and the standard library only.
set(CABLE_CORE_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CABLE_CORE_INCLUDE_DIR ${CABLE_CORE_DIR}/include)
set(CABLE_CORE_SOURCES
  # params: parameters, the config loader, initial states
  ${CABLE_CORE_DIR}/src/params/cable_params.cpp
  ${CABLE_CORE_DIR}/src/params/config_section.cpp
  ${CABLE_CORE_DIR}/src/params/config_loader.cpp
  ${CABLE_CORE_DIR}/src/params/states.cpp
  # dynamics: the paper's model, the joint springs, the fluid, the chain's equations of motion
  ${CABLE_CORE_DIR}/src/dynamics/azimuth_tracker.cpp
  ${CABLE_CORE_DIR}/src/dynamics/paper_model.cpp
  ${CABLE_CORE_DIR}/src/dynamics/elastic_joints.cpp
  ${CABLE_CORE_DIR}/src/dynamics/fluid.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_dynamics.cpp
  ${CABLE_CORE_DIR}/src/dynamics/chain_recursive.cpp
  # simulation: time stepping, end conditions, link frames
  ${CABLE_CORE_DIR}/src/simulation/cable_simulator.cpp
  ${CABLE_CORE_DIR}/src/simulation/link_frames.cpp
)
