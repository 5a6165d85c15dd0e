#!/usr/bin/env bash
# Installs what it needs, builds, and runs the main job: the demo umbilical (a fake ROV on a 50 m
# cable in a varying current) with roslaunch, and rviz where there is a display. Arguments go to
# roslaunch, e.g. `scripts/run.sh rviz:=false`. Stop with Ctrl-C.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_debian_packages
build_workspace >&2
source_devel_space
rviz=false
[ -n "${DISPLAY:-}" ] && rviz=true
exec roslaunch cable_dynamics demo.launch rviz:="$rviz" "$@"
