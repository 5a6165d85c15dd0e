#!/usr/bin/env bash
# Installs what the tests need, builds, and runs every test (gtest, pytest, rostest) through catkin.
# Exits non-zero when the build or any test fails; the last line is the summary.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_debian_packages
build_workspace
source_devel_space

rm -rf "$WS_DIR/build/test_results"
# The test executables on every core first (the pytests below run one at a time, -j1, so that timing
# tests do not compete; it would build them that way too, twice as slowly).
catkin_make -C "$WS_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 tests -j"$(nproc)"
# `run_tests` itself does not fail on a failing test; catkin_test_results does, below. Its three kinds
# in turn: the gtests on every core (computation only: no test among them judges wall time; ~200 s of
# them on one core), the pytests one at a time, then the rostests two at a time. A rostest mostly waits
# on the wall clock (its node runs in real time, its client at a fixed rate: 3 min of CPU in 13 min),
# each starts its own roscore on a free port, and those that judge timing (the ROV exchanges, the
# scheduler's catch-up) hold their bounds on a loaded machine: two at a time on 2 cores, 7.0 min
# against 13.2 min one at a time, every figure of the ROV exchanges within a few hundredths of a
# percent of the one-at-a-time run's (2026-12-05).
catkin_make -C "$WS_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests_cable_dynamics_gtest -j"$(nproc)"
catkin_make -C "$WS_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests_cable_dynamics_pytest -j1
catkin_make -C "$WS_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests_cable_dynamics_rostest -j2

# The README's commands as printed (test/tooling/test_readme_commands.py). Outside catkin's run_tests
# because one of them, scripts/run.sh, builds this workspace itself (nothing to do by then); under Xvfb
# because rviz opens a window. Its result goes with catkin's into the summary below.
readme_xml="$WS_DIR/build/test_results/cable_dynamics/pytest-readme_commands.xml"
set +e
xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 -m pytest -q -p no:cacheprovider \
  "$REPO_DIR/test/tooling/test_readme_commands.py" --junitxml="$readme_xml"
set -e
[ -f "$readme_xml" ] || { echo "test_readme_commands.py wrote no result"; exit 1; }

# The summary: every result file's test cases counted once (scripts/test_summary.py says why not
# catkin_test_results' own count, which counts each gtest case twice and adds rostest's wrapper entries).
# It lists the failed cases, says how many cases are parameter variations, ends with the line CI reads,
# "tests: N passed, N failed, N skipped", and exits 1 when a case failed or none ran.
set +e
/usr/bin/python3 "$REPO_DIR/scripts/test_summary.py" "$WS_DIR/build/test_results"
status=$?
set -e
exit $status
