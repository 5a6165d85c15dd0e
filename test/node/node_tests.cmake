# Tests of the ROS node, included from test/tests.cmake (rostest starts its own roscore).

# The node over ROS: rates, outputs, input guards, bad parameters.
add_rostest_gtest(test_cable_node test/cable_node.test test/node/test_cable_node.cpp)
target_include_directories(test_cable_node PRIVATE ${EIGEN3_INCLUDE_DIR} ${catkin_INCLUDE_DIRS} ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
target_link_libraries(test_cable_node ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
add_dependencies(test_cable_node cable_msgs_generate_messages_cpp cable_dynamics_node)
add_rostest(test/bad_config.test DEPENDENCIES cable_dynamics_node)
add_rostest(test/sim_time.test DEPENDENCIES cable_dynamics_node)
# Issue 11: log throttling (item 3), the launch file (item 5), catch-up bounded by wall time (item 6).
add_rostest(test/log_flood.test DEPENDENCIES cable_dynamics_node)
add_rostest(test/launch_file.test DEPENDENCIES cable_dynamics_node)
add_rostest(test/catch_up.test DEPENDENCIES cable_dynamics_node)
add_rostest(test/seabed.test DEPENDENCIES cable_dynamics_node)
# rostest finds the Python test nodes of this package in the devel space through these links.
# The rviz scene: the cable's cylinders, the bodies' shapes, the interactive marker driving the ROV.
add_rostest(test/scene.test DEPENDENCIES cable_dynamics_node)
# Issue 26: a light ROV exchanging poses and wrenches with the node, against the same case in the body mode;
# the node with the ROV simulated here (load.mode body).
add_rostest(test/rov_client.test DEPENDENCIES cable_dynamics_node cable_dynamics_python)
add_rostest(test/rov_client_elastic.test DEPENDENCIES cable_dynamics_node cable_dynamics_python)
add_rostest(test/body_mode.test DEPENDENCIES cable_dynamics_node)
foreach(script test_bad_config.py test_sim_time.py test_log_flood.py test_launch_file.py test_catch_up.py
    test_scene.py test_seabed_node.py test_rov_client.py test_body_mode_node.py test_fuzz_commands.py)
  execute_process(COMMAND ${CMAKE_COMMAND} -E create_symlink ${CMAKE_CURRENT_SOURCE_DIR}/test/node/${script}
    ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/${script})
endforeach()


# Hostile inputs (issue 11): huge positions, first poses, jumps and stamps, re-acquisition, reset ranges,
# divergence recovery; a second cable whose steps need substeps.
add_rostest_gtest(test_hostile_inputs test/hostile_inputs.test test/node/test_hostile_inputs.cpp)
target_include_directories(test_hostile_inputs PRIVATE ${EIGEN3_INCLUDE_DIR} ${catkin_INCLUDE_DIRS} ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
target_link_libraries(test_hostile_inputs ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
add_dependencies(test_hostile_inputs cable_msgs_generate_messages_cpp cable_dynamics_node)

# Issue 26: the coupling sized for the pose exchange, no roscore.
catkin_add_gtest(test_coupling_sizer test/node/test_coupling_sizer.cpp)
target_link_libraries(test_coupling_sizer cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})

# The node's ROS-light parts (guard, tracker, clock, builders' checks, options), no roscore.
catkin_add_gtest(test_node_parts test/node/test_node_parts.cpp)
target_link_libraries(test_node_parts cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})

# Fuzz: 100,000 hostile messages, counters compared exactly, every output checked.
add_rostest_gtest(test_fuzz_inputs test/fuzz_inputs.test test/node/test_fuzz_inputs.cpp)
target_include_directories(test_fuzz_inputs PRIVATE ${EIGEN3_INCLUDE_DIR} ${catkin_INCLUDE_DIRS} ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
target_link_libraries(test_fuzz_inputs ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
add_dependencies(test_fuzz_inputs cable_msgs_generate_messages_cpp cable_dynamics_node)
# Issue 27: hostile commands (winch speed and length, equilibrium resets, live tuning), every refusal counted.
add_rostest(test/fuzz_commands.test DEPENDENCIES cable_dynamics_node)

# The winch (pay out on winch/speed, haul in with winch/set_length, outputs for the deployed links only,
# the guards), and a node without a winch refusing both.
add_rostest_gtest(test_winch_node test/winch.test test/node/test_winch_node.cpp)
target_include_directories(test_winch_node PRIVATE ${EIGEN3_INCLUDE_DIR} ${catkin_INCLUDE_DIRS} ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
target_link_libraries(test_winch_node ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
add_dependencies(test_winch_node cable_msgs_generate_messages_cpp cable_dynamics_node)
# The winch's node parts (guard, range check, shaping without allocation, the new fields), no roscore.
catkin_add_gtest(test_node_winch_parts test/node/test_node_winch_parts.cpp)
target_link_libraries(test_node_winch_parts cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})
# Issue 25: the limits in cable_state, /diagnostics and the rviz tube.
catkin_add_gtest(test_node_limits_parts test/node/test_node_limits_parts.cpp)
target_link_libraries(test_node_limits_parts cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})
# The ends as bodies: a rolled vessel's hang-off point, a rotated ROV's attachment, their wrenches.
add_rostest_gtest(test_body_poses test/body_poses.test test/node/test_body_poses.cpp)
target_include_directories(test_body_poses PRIVATE ${EIGEN3_INCLUDE_DIR} ${catkin_INCLUDE_DIRS})
target_link_libraries(test_body_poses ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
add_dependencies(test_body_poses cable_dynamics_node)

# Issue 16: live tuning (retune against configured simulators, the checks against the loader's ranges;
# no roscore), then over ROS: dynamic_reconfigure (tuning.test), the nodelet (nodelet.test), the live
# plot (live_plot.test).
include(${CMAKE_CURRENT_LIST_DIR}/ros_parts_tests.cmake)
