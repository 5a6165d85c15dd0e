# Issue 16's ROS parts, included from test/node/node_tests.cmake.

# Live tuning without a roscore: retune() against simulators configured with the values, and the checks.
catkin_add_gtest(test_tuning test/node/test_tuning.cpp)
target_link_libraries(test_tuning cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})
# Over ROS: dynamic_reconfigure's client, the nodelet in a manager, the live plot headless.
add_rostest(test/tuning.test DEPENDENCIES cable_dynamics_node)
add_rostest(test/nodelet.test DEPENDENCIES cable_dynamics_nodelet)
add_rostest(test/live_plot.test DEPENDENCIES cable_dynamics_node)
foreach(script test_tuning_node.py test_nodelet.py test_live_plot.py)
  execute_process(COMMAND ${CMAKE_COMMAND} -E create_symlink ${CMAKE_CURRENT_SOURCE_DIR}/test/node/${script}
    ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/${script})
endforeach()
# No copies in the process: a subscriber there receives the SharedPublisher's own message object.
add_rostest_gtest(test_shared_messages test/shared_messages.test test/node/test_shared_messages.cpp)
target_link_libraries(test_shared_messages cable_dynamics_ros ${GTEST_LIBRARIES})
# Issue 22: the published joint efforts are the dynamics' own, with a turning clamp.
catkin_add_gtest(test_published_efforts test/node/test_published_efforts.cpp)
target_link_libraries(test_published_efforts cable_dynamics_ros ${GTEST_MAIN_LIBRARIES})
