#!/usr/bin/env bash
# Builds unimap and runs the main job: `unimap demo` simulates the paper's
# tunnel with the rotating Hokuyo, maps it, evaluates it against the ground
# truth and prints the result beside the paper's numbers. Everything it
# writes goes to ./unimap-demo/ (report.html, map.pcd / map.ply / map.bt,
# trajectories, metrics.json). Extra arguments go to `unimap demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j2 --target unimap unimap_payload_fixed_3d \
  unimap_payload_rotating_3d unimap_payload_rotating_2d
"$BUILD_DIR/bin/unimap" demo "$@"
