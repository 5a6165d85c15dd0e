# Shared by scripts/run.sh and scripts/test.sh: environment, Debian packages, catkin workspace build.
# Sourced, not run.

REPO_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# The catkin workspace that builds this repository (its src/ holds a link to the repo).
WS_DIR="${CABLE_WS:-$REPO_DIR/.ws}"

# ROS 1 on Debian lives in /usr and its tools need Debian's python3 with the ROS modules: put /usr/bin
# ahead of any other python3 (pyenv, venv) on PATH. Harmless on a plain Debian machine.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
unset PYTHONHOME PYTHONPATH

DEB_PACKAGES=(
  build-essential cmake catkin ros-core-dev ros-message-generation python3-rospy python3-rostest
  librostest-dev libgtest-dev googletest libtf2-ros-dev liburdfdom-dev libeigen3-dev libyaml-cpp-dev
  nlohmann-json3-dev libstd-msgs-dev libgeometry-msgs-dev libsensor-msgs-dev libvisualization-msgs-dev
  libdiagnostic-msgs-dev python3-std-msgs python3-geometry-msgs python3-sensor-msgs
  python3-sympy python3-numpy python3-pytest python3-yaml python3-matplotlib libmujoco-dev
  libtf2-eigen-dev libtinyxml-dev rviz xvfb imagemagick python3-tf2-ros python3-diagnostic-msgs
  python3-visualization-msgs python3-rosgraph-msgs python3-rosmsg python3-roslaunch python3-rosunit python3-roslib
  python3-rosgraph libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure libnodeletlib-dev
  libnodeletlib-tools python3-nodelet
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
  "${sudo[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
}

# Builds the workspace (Release) with catkin_make; extra arguments go to catkin_make.
build_workspace() {
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
