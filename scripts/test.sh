#!/usr/bin/env bash
# Configures, builds (2 jobs) and runs every test: unit, conformance,
# integration; then the unit tests and fuzz regression inputs again in an
# ASan + UBSan build (docs/reliability.md; UNIMAP_SKIP_SANITIZERS=1 skips that).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j2
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
if [ "${UNIMAP_SKIP_SANITIZERS:-0}" != 1 ]; then bash scripts/sanitize.sh asan-unit; fi
