#!/usr/bin/env bash
# Installs unimap's build and test dependencies from Debian's packages.
# report.html inlines libjs-three and libjs-dygraphs at build time; the
# figures are drawn with cairo; the report's test opens it in chromium,
# driven by a python3 script (standard library only).
set -euo pipefail
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
  build-essential cmake git ca-certificates pkg-config \
  libeigen3-dev liboctomap-dev libdynamicedt3d-dev libceres-dev \
  libboost-dev libboost-filesystem-dev libpcl-dev libyaml-cpp-dev \
  libgtest-dev libgmock-dev libbenchmark-dev libtbb-dev libcli11-dev libspdlog-dev robin-map-dev \
  libbz2-dev zlib1g-dev librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev libsqlite3-dev libfastcdr-dev \
  nlohmann-json3-dev libcairo2-dev fonts-dejavu-core libjs-three libjs-dygraphs \
  chromium python3 python3-dev python3-numpy pybind11-dev clang-format-14
