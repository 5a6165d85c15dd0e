#!/usr/bin/env bash
# Runs every preset in config/ for its configured duration and writes docs/plots/<preset>.png (and the
# CSV under the workspace's plots/, scripts/common.sh: beside the repository). Needs a build (scripts/run.sh or scripts/test.sh builds one).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
mkdir -p "$REPO_DIR/docs/plots" "$WS_DIR/plots"
for config in "$REPO_DIR"/config/*.yaml; do
  name="$(basename "$config" .yaml)"
  "$WS_DIR/devel/lib/cable_dynamics/cable_sim" --config "$config" --output "$WS_DIR/plots/$name.csv" \
    --plot "$REPO_DIR/docs/plots/$name.png" --sample 0.02
done
