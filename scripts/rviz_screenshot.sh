#!/usr/bin/env bash
# The rviz screenshot of the README (docs/rviz_interactive.png): demo.launch with the interactive marker under
# Xvfb (software GL), the ROV dragged once through the marker's feedback topic as rviz would, then
# ImageMagick's `import -window root`. Usage: bash scripts/rviz_screenshot.sh [OUT.png] [settle seconds]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
out="$(realpath -m "${1:-$REPO_DIR/docs/rviz_interactive.png}")"
settle="${2:-40}"
source_devel_space
display=":$((90 + RANDOM % 9))"
export LIBGL_ALWAYS_SOFTWARE=1 DISPLAY="$display"
export ROS_MASTER_URI="http://localhost:$((11400 + RANDOM % 500))"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; }
trap cleanup EXIT
Xvfb "$display" -screen 0 1400x900x24 >/dev/null 2>&1 &
pids+=($!)
sleep 2
roslaunch -p "${ROS_MASTER_URI##*:}" cable_dynamics demo.launch interactive:=true >/tmp/rviz_screenshot_launch.log 2>&1 &
pids+=($!)
sleep 15
# Drag the ROV: one POSE_UPDATE on the marker's feedback topic (what rviz sends while the box is dragged).
rostopic pub -1 /umbilical/rov_target_marker/feedback visualization_msgs/InteractiveMarkerFeedback \
  "{header: {frame_id: world}, client_id: screenshot, marker_name: rov_target, control_name: move_3d, event_type: 1,
    pose: {position: {x: 12.0, y: 6.0, z: -30.0}, orientation: {x: 0.0, y: 0.0, z: 0.38268, w: 0.92388}}}" >/dev/null
sleep "$settle"
import -window root "$out"
echo "[cable_dynamics] screenshot: $out"
