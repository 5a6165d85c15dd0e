#!/usr/bin/env bash
# The README's rviz screenshots: the demo with the interactive marker under Xvfb (software GL); the ROV is
# dragged through the marker's feedback topic as rviz would; then ImageMagick's `import -window root`, once
# with the view of config/umbilical.rviz (OVERVIEW.png) and once from close to the ROV (CLOSEUP.png), where
# the cable's real diameter shows.
# Usage: bash scripts/rviz_screenshot.sh [OVERVIEW.png] [CLOSEUP.png]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
overview="$(realpath -m "${1:-$REPO_DIR/docs/rviz_interactive.png}")"
closeup="$(realpath -m "${2:-$REPO_DIR/docs/rviz_closeup.png}")"
source_devel_space
display=":$((90 + RANDOM % 9))"
export LIBGL_ALWAYS_SOFTWARE=1 DISPLAY="$display"
port=$((11400 + RANDOM % 500))
export ROS_MASTER_URI="http://localhost:$port"
work="$(mktemp -d)"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
Xvfb "$display" -screen 0 1400x900x24 >/dev/null 2>&1 &
pids+=($!)
sleep 2
# demo.launch interactive:=true, with a fixed colour scale (the demo's default is the largest tension seen,
# which the start's transient sets) so the cable's colours read.
python3 - "$REPO_DIR/config/demo_rov.yaml" "$work/demo.yaml" <<'PY'
import sys, yaml
cfg = yaml.safe_load(open(sys.argv[1]))
cfg.setdefault("ros", {})["tension_scale"] = 40.0
yaml.safe_dump(cfg, open(sys.argv[2], "w"))
PY
roslaunch -p "$port" cable_dynamics umbilical.launch config:="$work/demo.yaml" interactive:=true rviz:=false \
  >"$work/launch.log" 2>&1 &
pids+=($!)
rviz -d "$REPO_DIR/config/umbilical.rviz" >"$work/rviz.log" 2>&1 &
rviz_pid=$!
pids+=($rviz_pid)
sleep 15
# Drag the ROV as a user would: POSE_UPDATEs on the marker's feedback topic (what rviz sends while the box
# is dragged), from where the marker starts to (10, 8, -18) m in 40 s, turning it by 30 degrees.
python3 - <<'PY'
import rospy
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerInit
rospy.init_node("screenshot_drag")
start = rospy.wait_for_message("/umbilical/rov_target_marker/update_full", InteractiveMarkerInit, 30).markers[0].pose
pub = rospy.Publisher("/umbilical/rov_target_marker/feedback", InteractiveMarkerFeedback, queue_size=10)
rospy.sleep(1.5)
a, b = (start.position.x, start.position.y, start.position.z), (10.0, 8.0, -18.0)
steps = 400
for i in range(steps + 1):
    f = InteractiveMarkerFeedback(client_id="screenshot", marker_name="rov_target", control_name="move_3d",
                                  event_type=InteractiveMarkerFeedback.POSE_UPDATE)
    f.header.frame_id = "world"
    f.header.stamp = rospy.Time.now()
    s = i / steps
    f.pose.position.x, f.pose.position.y, f.pose.position.z = (a[j] + s * (b[j] - a[j]) for j in range(3))
    f.pose.orientation.z, f.pose.orientation.w = 0.259 * s, (1.0 - (0.259 * s) ** 2) ** 0.5
    pub.publish(f)
    rospy.sleep(0.1)
PY
sleep 15
import -window root "$overview"
echo "[cable_dynamics] screenshot: $overview"
# The close view: the same config with the camera 9 m from the ROV.
python3 - "$REPO_DIR/config/umbilical.rviz" "$work/closeup.rviz" <<'PY'
import sys, yaml
cfg = yaml.safe_load(open(sys.argv[1]))
view = cfg["Visualization Manager"]["Views"]["Current"]
view.update({"Distance": 9.0, "Focal Point": {"X": 9.0, "Y": 7.0, "Z": -19.0}, "Pitch": 0.35, "Yaw": 3.9})
yaml.safe_dump(cfg, open(sys.argv[2], "w"))
PY
kill "$rviz_pid"
wait "$rviz_pid" 2>/dev/null || true
rviz -d "$work/closeup.rviz" >"$work/rviz2.log" 2>&1 &
pids+=($!)
sleep 20
import -window root "$closeup"
echo "[cable_dynamics] screenshot: $closeup"
