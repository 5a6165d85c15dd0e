# Shared by scripts/run.sh and scripts/test.sh: environment, Debian packages, catkin workspace build.
# Sourced, not run.

REPO_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# The catkin workspace that builds this repository: its src/ holds a link to the repo, so it must not sit
# inside the repo (tools that walk a package's folder, rosrun's `find -L` and rospack's crawl, would follow
# the link back into it: "File system loop detected"). Beside the repository by default,
# `<parent>/<repo folder>_ws`; CABLE_WS=/some/path overrides it; where the parent is not writable, under
# ~/.cache.
default_workspace() {
  local parent name
  parent="$(dirname "$REPO_DIR")"
  name="$(basename "$REPO_DIR")_ws"
  if [ -w "$parent" ] || [ -d "$parent/$name" ]; then
    echo "$parent/$name"
  else
    echo "${XDG_CACHE_HOME:-$HOME/.cache}/cable_dynamics/$name"
  fi
}
WS_DIR="${CABLE_WS:-$(default_workspace)}"
case "$WS_DIR/" in
  "$REPO_DIR"/*)
    echo "[cable_dynamics] CABLE_WS=$WS_DIR is inside the repository $REPO_DIR: its src/ link would make a" \
      "file system loop; choose a folder outside it" >&2
    return 2 2>/dev/null || exit 2 ;;
esac

# ROS 1 on Debian lives in /usr and its tools need Debian's python3 with the ROS modules: put /usr/bin
# ahead of any other python3 (pyenv, venv) on PATH. Harmless on a plain Debian machine.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
unset PYTHONHOME PYTHONPATH

DEB_PACKAGES=(
  build-essential cmake catkin ros-core-dev ros-message-generation python3-rospy python3-rostest
  librostest-dev libgtest-dev googletest libtf2-ros-dev liburdfdom-dev libeigen3-dev libyaml-cpp-dev
  nlohmann-json3-dev libstd-msgs-dev libgeometry-msgs-dev libsensor-msgs-dev libvisualization-msgs-dev
  libdiagnostic-msgs-dev libnav-msgs-dev python3-std-msgs python3-geometry-msgs python3-sensor-msgs
  python3-sympy python3-numpy python3-scipy python3-pytest python3-yaml python3-matplotlib libmujoco-dev
  libtf2-eigen-dev libtinyxml-dev rviz xvfb imagemagick python3-tf2-ros python3-diagnostic-msgs
  python3-visualization-msgs python3-nav-msgs python3-rosgraph-msgs python3-rosmsg python3-roslaunch python3-rosunit python3-roslib
  python3-rosgraph pybind11-dev python3-pybind11 python3-interactive-markers
  # A ROS user's everyday commands: rosrun, roscd, rosed (rosbash; ros-core only recommends it, and the
  # install below takes no recommends), rospack, rostopic, rosservice, rosparam, rosnode, rosmsg,
  # roslaunch, rosbag (play, info, record) and rosbag's C++ storage that cable_sim's --bag writes with.
  rosbash rospack-tools python3-rostopic python3-rosservice python3-rosparam python3-rosnode python3-rosbag
  librosbag-storage-dev libtf2-msgs-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure libnodeletlib-dev
  libnodeletlib-tools python3-nodelet
  # cable_sweep: design sweeps on Dask's distributed scheduler (dask-scheduler, dask-worker)
  python3-distributed
)

# Installs the Debian packages that are missing (apt-get update first), as root or through sudo.
install_debian_packages() {
  local missing=()
  for p in "${DEB_PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    echo "[cable_dynamics] Debian packages: all present"
    return 0
  fi
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "[cable_dynamics] installing: ${missing[*]}"
  # Waits for another apt-get holding the lock (a parallel build on the same machine) instead of failing.
  "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=600 update
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y \
    --no-install-recommends "${missing[@]}"
}

# Builds the workspace (Release) with catkin_make; extra arguments go to catkin_make.
build_workspace() {
  echo "[cable_dynamics] workspace: $WS_DIR" >&2
  mkdir -p "$WS_DIR/src"
  ln -sfn "$REPO_DIR" "$WS_DIR/src/cable_dynamics"
  catkin_make -C "$WS_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
    -j"$(nproc)" "$@"
}

# Makes the devel space's environment current (ROS_PACKAGE_PATH, CMAKE_PREFIX_PATH, ...).
source_devel_space() {
  # setup.bash reads unset variables: relax `set -u` around it.
  local had_u=0
  [[ $- == *u* ]] && had_u=1 && set +u
  # shellcheck disable=SC1091
  source "$WS_DIR/devel/setup.bash"
  ((had_u)) && set -u
  return 0
}
