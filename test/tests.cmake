# Tests, run by `catkin_make run_tests` (see scripts/test.sh). Included from the root CMakeLists.txt.

# Core library, no roscore.
catkin_add_gtest(test_config_loader test/test_config_loader.cpp)
target_link_libraries(test_config_loader cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_config_loader PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# docs/CONFIG.md names exactly the keys the loader reads.
catkin_add_gtest(test_config_keys test/test_config_keys.cpp)
target_link_libraries(test_config_keys cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_config_keys PRIVATE CABLE_DOCS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/docs")

# Parameters filled in by hand meet the config's ranges (params/key_ranges.h) in the simulator's gate.
catkin_add_gtest(test_range_gate test/test_range_gate.cpp)
target_link_libraries(test_range_gate cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_paper_model test/test_paper_model.cpp)
target_link_libraries(test_paper_model cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_elastic_joints test/test_elastic_joints.cpp)
target_link_libraries(test_elastic_joints cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_elastic_joints PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

catkin_add_gtest(test_cable_model_cli test/test_cable_model_cli.cpp)
target_link_libraries(test_cable_model_cli cable_dynamics_tools ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_cable_model_cli PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# Python tests (Debian's python3 with sympy/numpy/pytest), registered like catkin's own test types so
# that catkin_test_results counts them.
set(CABLE_PYTHON /usr/bin/python3)
function(cable_add_pytest name file)
  set(xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/pytest-${name}.xml)
  # catkin splits COMMAND on ';': pass the environment as one space-separated string.
  string(REPLACE ";" " " environment "${ARGN}")
  catkin_run_tests_target("pytest" ${name} "pytest-${name}.xml"
    COMMAND "${CMAKE_COMMAND} -E env ${environment} ${CABLE_PYTHON} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_SOURCE_DIR}/${file} --junitxml=${xml}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
endfunction()

cable_add_pytest(sympy_reference test/test_sympy_reference.py
  CABLE_MODEL_BIN=$<TARGET_FILE:cable_model> CABLE_TEST_CONFIG=${CMAKE_CURRENT_SOURCE_DIR}/config/default.yaml)
cable_add_pytest(messages_visible test/test_messages_visible.py)
add_dependencies(run_tests_cable_dynamics_pytest_sympy_reference cable_model)

# ROS graph tests (rostest starts its own roscore).
find_package(rostest REQUIRED)
add_rostest(test/load_config.test)

catkin_add_gtest(test_chain_dynamics test/test_chain_dynamics.cpp)
target_link_libraries(test_chain_dynamics cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_link_drag test/test_link_drag.cpp)
target_link_libraries(test_link_drag cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_azimuth_tracker test/test_azimuth_tracker.cpp)
target_link_libraries(test_azimuth_tracker cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_simulator test/test_simulator.cpp)
target_link_libraries(test_simulator cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_axial_elasticity test/test_axial_elasticity.cpp)
target_link_libraries(test_axial_elasticity cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_end_fixity test/test_end_fixity.cpp)
target_link_libraries(test_end_fixity cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
# The limits: bend radius against a circular arc, utilisation, clearance, the keys' refusals.
catkin_add_gtest(test_cable_limits test/test_cable_limits.cpp)
target_link_libraries(test_cable_limits cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_statics test/test_statics.cpp)
target_link_libraries(test_statics cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_statics PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
catkin_add_gtest(test_sections test/test_sections.cpp)
target_link_libraries(test_sections cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_seabed test/test_seabed.cpp)
target_link_libraries(test_seabed cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_seabed PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# Issue 26: the ROV's port (stiffness and damping of the coupling) and the first-order hold of a target.
catkin_add_gtest(test_coupling_port test/test_coupling_port.cpp)
target_link_libraries(test_coupling_port cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_coupling_integral test/test_coupling_integral.cpp)
target_link_libraries(test_coupling_integral cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_rov_body test/test_rov_body.cpp)
target_link_libraries(test_rov_body cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_semi_implicit_body test/test_semi_implicit_body.cpp)
target_link_libraries(test_semi_implicit_body cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_step_check test/test_step_check.cpp)
target_link_libraries(test_step_check cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_step_check PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
catkin_add_gtest(test_stable_step test/test_stable_step.cpp)
target_link_libraries(test_stable_step cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_stable_step PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# The implicit integrator (issue 15): its recursion against a dense solve, and the scheme against RK4,
# closed forms and the statics.
catkin_add_gtest(test_implicit_recursion test/test_implicit_recursion.cpp)
target_link_libraries(test_implicit_recursion cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_implicit_scheme test/test_implicit_scheme.cpp)
target_link_libraries(test_implicit_scheme cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_implicit_scheme PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
# Its booking of the seabed's losses against the first law.
catkin_add_gtest(test_implicit_contact_losses test/test_implicit_contact_losses.cpp)
target_link_libraries(test_implicit_contact_losses cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# Multibody reference: MuJoCo from Debian (libmujoco-dev).
# (Debian's mujocoConfig.cmake names /usr/include/libqhull_r, which the package does not install, so the
# library and header are found directly.)
find_library(MUJOCO_LIBRARY mujoco REQUIRED)
find_path(MUJOCO_INCLUDE_DIR mujoco/mujoco.h REQUIRED)
catkin_add_gtest(test_mujoco_reference test/test_mujoco_reference.cpp test/reference/mujoco_chain.cpp)
target_include_directories(test_mujoco_reference PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/test ${MUJOCO_INCLUDE_DIR})
target_link_libraries(test_mujoco_reference cable_dynamics_core ${MUJOCO_LIBRARY} ${GTEST_MAIN_LIBRARIES})

cable_add_pytest(presets test/test_presets.py CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>)
add_dependencies(run_tests_cable_dynamics_pytest_presets cable_sim)
# The Python module (cable_dynamics/python/): run in the devel space's environment, and once more through
# a fresh shell that sources its setup.bash, as the README's example is run.
cable_add_pytest(python_bindings test/test_python_bindings.py
  CABLE_MODEL_BIN=$<TARGET_FILE:cable_model> CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>
  CABLE_DEVEL_SETUP=${CATKIN_DEVEL_PREFIX}/setup.bash)
add_dependencies(run_tests_cable_dynamics_pytest_python_bindings cable_model cable_sim cable_dynamics_python)
# Issue 26: load.mode body against the same ROV written apart (scripts/simple_rov.py) in a 1 ms lockstep.
cable_add_pytest(body_vs_lockstep test/test_body_vs_lockstep.py)
add_dependencies(run_tests_cable_dynamics_pytest_body_vs_lockstep cable_dynamics_python)
cable_add_pytest(unreliable_runs test/test_unreliable_runs.py CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>)
add_dependencies(run_tests_cable_dynamics_pytest_unreliable_runs cable_sim)
cable_add_pytest(beam_catenary test/test_beam_catenary.py CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>)
add_dependencies(run_tests_cable_dynamics_pytest_beam_catenary cable_sim)
# Issue 25: cable_sweep on a local Dask cluster and through dask-scheduler / dask-worker processes, against
# direct cable_sim runs of its cases.
cable_add_pytest(cable_sweep test/test_cable_sweep.py CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>
  CABLE_SWEEP_BIN=${CMAKE_CURRENT_SOURCE_DIR}/scripts/cable_sweep)
add_dependencies(run_tests_cable_dynamics_pytest_cable_sweep cable_sim cable_dynamics_python)

# The node over ROS (rostest): test/node/node_tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/node/node_tests.cmake)

# The cable URDF parses back with urdfdom.
catkin_add_gtest(test_cable_urdf test/test_cable_urdf.cpp)
target_link_libraries(test_cable_urdf cable_dynamics_urdf ${GTEST_MAIN_LIBRARIES})

# No heap allocation in a step: the core compiled again with EIGEN_RUNTIME_NO_MALLOC, for this test only.
add_library(cable_dynamics_core_nomalloc STATIC ${CABLE_CORE_SOURCES})
target_compile_definitions(cable_dynamics_core_nomalloc PUBLIC EIGEN_RUNTIME_NO_MALLOC)
# Eigen checks the guard with eigen_assert: keep assertions on (no NDEBUG) in this library and test.
target_compile_options(cable_dynamics_core_nomalloc PUBLIC -UNDEBUG)
target_include_directories(cable_dynamics_core_nomalloc PUBLIC ${CABLE_CORE_INCLUDE_DIR} ${EIGEN3_INCLUDE_DIR})
target_link_libraries(cable_dynamics_core_nomalloc PUBLIC yaml-cpp)
catkin_add_gtest(test_no_allocation test/test_no_allocation.cpp)
target_link_libraries(test_no_allocation cable_dynamics_core_nomalloc ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_formulations test/test_formulations.cpp)
target_link_libraries(test_formulations cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_formulations PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

catkin_add_gtest(test_winch test/test_winch.cpp)
target_link_libraries(test_winch cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# Issue 23: a winch paying out a stretching cable (unstretched length; the line pull at the drum).
catkin_add_gtest(test_winch_stretch test/test_winch_stretch.cpp)
target_link_libraries(test_winch_stretch cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# Issue 27 item 1: the line pull through the links the winch adds (rov_dive.yaml and a stiff tether).
catkin_add_gtest(test_winch_line_pull test/test_winch_line_pull.cpp)
target_link_libraries(test_winch_line_pull cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_winch_line_pull PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

catkin_add_gtest(test_equilibrium_start test/test_equilibrium_start.cpp)
target_link_libraries(test_equilibrium_start cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

catkin_add_gtest(test_body_motion test/test_body_motion.cpp)
target_link_libraries(test_body_motion cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# cable_sim's CSV and rosbag outputs.
include(${CMAKE_CURRENT_LIST_DIR}/tooling/tooling_tests.cmake)

# Issue 22: what was written twice, each checked against a truth outside its own path.
catkin_add_gtest(test_written_once test/test_written_once.cpp)
target_link_libraries(test_written_once cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
catkin_add_gtest(test_force_modules test/test_force_modules.cpp)
target_link_libraries(test_force_modules cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# The exact anchor (load.anchor exact): a V of two rods against the physical pendulum and its support
# reactions, the statics' tip on the anchor, a mooring chain's hold at each integrator's recommended step.
catkin_add_gtest(test_exact_anchor test/test_exact_anchor.cpp)
target_link_libraries(test_exact_anchor cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_exact_anchor PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config"
                           CABLE_BENCH_DIR="${CMAKE_CURRENT_SOURCE_DIR}/bench")

# Neighbouring links cannot fold through each other (forces/fold_stop.h; issue 27 item 4).
catkin_add_gtest(test_fold_stop test/test_fold_stop.cpp)
target_link_libraries(test_fold_stop cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# Static friction on the seabed: an anchor per contact point (forces/contact.h; issue 27 item 5).
catkin_add_gtest(test_static_friction test/test_static_friction.cpp)
target_link_libraries(test_static_friction cable_dynamics_core ${GTEST_MAIN_LIBRARIES})

# The implicit step's recommended step against a tenth of it on the implicit presets (stable_step.cpp).
catkin_add_gtest(test_implicit_step_size test/test_implicit_step_size.cpp)
target_link_libraries(test_implicit_step_size cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_compile_definitions(test_implicit_step_size PRIVATE CABLE_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# The statics' start from the elastic catenary (statics/catenary_start.cpp; issue 24's statics target).
catkin_add_gtest(test_catenary_start test/test_catenary_start.cpp)
target_link_libraries(test_catenary_start cable_dynamics_core ${GTEST_MAIN_LIBRARIES})
target_include_directories(test_catenary_start PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cable_dynamics/core/src/statics)
target_compile_definitions(test_catenary_start PRIVATE BENCH_LINES_DIR="${CMAKE_CURRENT_SOURCE_DIR}/bench/moordyn/lines")
