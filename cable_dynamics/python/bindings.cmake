# The Python package `cable_dynamics` (pybind11 from Debian: pybind11-dev). Included from the root
# CMakeLists.txt. dynamic_reconfigure generates a Python package of the project's name (cable_dynamics.cfg,
# with an empty __init__.py) in the devel space: the compiled module is `cable_dynamics._bindings` inside
# it, and our __init__.py, copied over the empty one after the generation, re-exports it; so
# `import cable_dynamics` works after `source devel/setup.bash`, and the same in the install space.
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
# cable_dynamics_tools: cable_sim's run (sampled_run.h) and CSV, which Simulator.run shares with it.
target_link_libraries(cable_dynamics_python PRIVATE cable_dynamics_core cable_dynamics_tools)
set(CABLE_PYTHON_PACKAGE_DIR ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_PYTHON_DESTINATION})
set_target_properties(cable_dynamics_python PROPERTIES
  OUTPUT_NAME _bindings
  LIBRARY_OUTPUT_DIRECTORY ${CABLE_PYTHON_PACKAGE_DIR})
add_dependencies(cable_dynamics_python ${PROJECT_NAME}_gencfg)
add_custom_command(TARGET cable_dynamics_python POST_BUILD
  COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_CURRENT_LIST_DIR}/__init__.py ${CABLE_PYTHON_PACKAGE_DIR}/__init__.py)
install(TARGETS cable_dynamics_python LIBRARY DESTINATION ${CATKIN_PACKAGE_PYTHON_DESTINATION})
install(FILES ${CMAKE_CURRENT_LIST_DIR}/__init__.py DESTINATION ${CATKIN_PACKAGE_PYTHON_DESTINATION})
# cable_sweep's library, the subpackage cable_dynamics.sweep (pure Python, cable_dynamics/python/sweep/):
# linked into the devel space's package at configure time (an edit needs no rebuild), installed beside
# the module.
file(MAKE_DIRECTORY ${CABLE_PYTHON_PACKAGE_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E create_symlink ${CMAKE_CURRENT_LIST_DIR}/sweep
  ${CABLE_PYTHON_PACKAGE_DIR}/sweep)
install(DIRECTORY ${CMAKE_CURRENT_LIST_DIR}/sweep DESTINATION ${CATKIN_PACKAGE_PYTHON_DESTINATION}
  FILES_MATCHING PATTERN "*.py")
