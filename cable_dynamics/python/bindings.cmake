# The Python module `cable_dynamics` (pybind11 from Debian: pybind11-dev). Included from the root
# CMakeLists.txt. Built into the devel space's python directory, so `import cable_dynamics` works after
# `source devel/setup.bash`, and installed into the install space's.
# Debian's python3 (the one catkin was configured with), found with its development part before pybind11:
# a package that catkin's components pull in (rosbag_storage) finds Python3 without it, and pybind11 then
# picks its FindPython mode without python3_add_library.
if(PYTHON_EXECUTABLE)
  set(Python3_EXECUTABLE ${PYTHON_EXECUTABLE})
endif()
find_package(Python3 COMPONENTS Interpreter Development REQUIRED)
find_package(pybind11 CONFIG REQUIRED)
pybind11_add_module(cable_dynamics_python MODULE
  ${CMAKE_CURRENT_LIST_DIR}/src/module.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/python_simulator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/config_from_python.cpp
)
target_link_libraries(cable_dynamics_python PRIVATE cable_dynamics_core)
set_target_properties(cable_dynamics_python PROPERTIES
  OUTPUT_NAME cable_dynamics
  LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_PYTHON_DESTINATION})
install(TARGETS cable_dynamics_python LIBRARY DESTINATION ${CATKIN_GLOBAL_PYTHON_DESTINATION})
