#!/usr/bin/env bash
# Installs what it needs, builds, and runs the main job: for now the model generator on the default
# config (prints M, h, G, K, D as JSON). Arguments are passed to cable_model, e.g.
#   scripts/run.sh --set cable.links=4 --random-state 1
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_debian_packages
build_workspace >&2
source_devel_space
exec "$WS_DIR/devel/lib/cable_dynamics/cable_model" --config "$REPO_DIR/config/default.yaml" "$@"
