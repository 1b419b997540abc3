#!/usr/bin/env bash
# Installs unimap's build and test dependencies from Debian's packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
  build-essential cmake git ca-certificates pkg-config \
  libeigen3-dev liboctomap-dev libdynamicedt3d-dev libceres-dev \
  libboost-dev libboost-filesystem-dev libpcl-dev libyaml-cpp-dev \
  libgtest-dev libgmock-dev libbenchmark-dev libtbb-dev libcli11-dev libspdlog-dev libstb-dev robin-map-dev \
  libbz2-dev librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev
