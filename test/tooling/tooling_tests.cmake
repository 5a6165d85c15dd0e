# Tests of the tools' output (cable_sim's CSV writer and its rosbag). Included from test/tests.cmake.

catkin_add_gtest(test_csv_output test/tooling/test_csv_output.cpp)
target_link_libraries(test_csv_output cable_dynamics_tools ${GTEST_MAIN_LIBRARIES})

# cable_sim --bag: the bag read back with Debian's Python rosbag (an independent reader) against the CSV of
# the same run, and `rosbag info` on it.
cable_add_pytest(bag_output test/tooling/test_bag_output.py CABLE_SIM_BIN=$<TARGET_FILE:cable_sim>
  CABLE_CONFIG_DIR=${CMAKE_CURRENT_SOURCE_DIR}/config)
add_dependencies(run_tests_cable_dynamics_pytest_bag_output cable_sim)

# scripts/test_summary.py, the suite's summary line: each test case counted once (not catkin's double count).
cable_add_pytest(summary_count test/tooling/test_summary_count.py)
