#!/usr/bin/env bash
# Builds unimap and runs the main job. Until the mapping demo lands, the main
# job lists the payload plugins and shows a platform's effective parameters.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j2 --target unimap unimap_payload_fixed_3d \
  unimap_payload_rotating_3d unimap_payload_rotating_2d
"$BUILD_DIR/bin/unimap" plugins
"$BUILD_DIR/bin/unimap" config --platform configs/platforms/rotating_hokuyo.yaml
