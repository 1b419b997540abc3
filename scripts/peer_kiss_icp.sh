#!/usr/bin/env bash
# Builds KISS-ICP's C++ core from ../shared/peers (offline, Debian packages
# plus the Sophus copy there; nothing of it enters the repository) and runs
# it on a KITTI-style folder of PCD sweeps with times.txt, writing its
# trajectory beside ours for docs/robustness.md:
#   bash scripts/peer_kiss_icp.sh [FOLDER] [OUT_DIR]
# (defaults: ../shared/data/kitti00, build-peers/kitti00). Not part of the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
PEERS="${PEERS:-../shared/peers}"
FOLDER="${1:-../shared/data/kitti00}"
OUT="${2:-build-peers/kitti00}"
B="${PEER_BUILD_DIR:-build-peers}"
if [ ! -d "$PEERS/kiss-icp/cpp/kiss_icp" ]; then
  echo "no KISS-ICP peer at $PEERS/kiss-icp (see its README); nothing to compare" >&2
  exit 77
fi
SUDO=""; [ "$(id -u)" != "0" ] && SUDO="sudo"
if ! dpkg -s libtbb-dev robin-map-dev >/dev/null 2>&1; then
  $SUDO apt-get install -y -q --no-install-recommends libeigen3-dev libtbb-dev robin-map-dev
fi
if [ ! -f "$B/deps/share/sophus/cmake/SophusConfig.cmake" ] && [ ! -d "$B/deps/share/sophus" ]; then
  cmake -S "$PEERS/sophus-1.24.6" -B "$B/sophus" -DCMAKE_INSTALL_PREFIX="$PWD/$B/deps" \
    -DBUILD_SOPHUS_TESTS=OFF -DBUILD_SOPHUS_EXAMPLES=OFF -DBUILD_PYTHON_BINDINGS=OFF > /dev/null
  cmake --install "$B/sophus" > /dev/null
fi
cmake -S "$PEERS/kiss-icp/cpp/kiss_icp" -B "$B/kiss" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PWD/$B/deps" \
  -DUSE_CCACHE=OFF -DUSE_SYSTEM_EIGEN3=ON -DUSE_SYSTEM_SOPHUS=ON -DUSE_SYSTEM_TSL-ROBIN-MAP=ON \
  -DUSE_SYSTEM_TBB=ON > /dev/null
cmake --build "$B/kiss" -j2 > /dev/null
# The runner (bench/peers/KissIcpRunner.cpp) against the peer's static libraries.
mkdir -p "$B/runner"
cat > "$B/runner/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(kiss_icp_runner CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(Sophus REQUIRED)
find_package(TBB REQUIRED)
add_executable(kiss_icp_runner $PWD/bench/peers/KissIcpRunner.cpp)
target_include_directories(kiss_icp_runner PRIVATE $PWD/$PEERS/kiss-icp/cpp)
target_link_libraries(kiss_icp_runner PRIVATE $PWD/$B/kiss/pipeline/libkiss_icp_pipeline.a
  $PWD/$B/kiss/core/libkiss_icp_core.a Eigen3::Eigen Sophus::Sophus TBB::tbb)
CMAKE
cmake -S "$B/runner" -B "$B/runner/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PWD/$B/deps" > /dev/null
cmake --build "$B/runner/build" -j2 > /dev/null
mkdir -p "$OUT"
"$B/runner/build/kiss_icp_runner" "$FOLDER" "$OUT/kiss_icp.tum"
echo "wrote $OUT/kiss_icp.tum"
