# Source this (bash) to use the build in your shell: `source scripts/env.bash` from the repository root,
# after `bash scripts/run.sh` or `bash scripts/test.sh` has built the workspace. It puts Debian's python3
# first on PATH (the ROS tools need its modules) and sources the workspace's devel space, wherever
# scripts/common.sh put it (beside the repository, or $CABLE_WS). Then rosrun, roslaunch, rostopic, rosmsg,
# rosbag know cable_dynamics and cable_msgs.
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" || return
if [ ! -f "$WS_DIR/devel/setup.bash" ]; then
  echo "[cable_dynamics] no build in $WS_DIR yet: run bash scripts/run.sh or bash scripts/test.sh first" >&2
  return 1
fi
source_devel_space
echo "[cable_dynamics] using the workspace $WS_DIR" >&2
