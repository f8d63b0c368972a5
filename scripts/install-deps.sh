#!/usr/bin/env bash
# Installs the Debian 12 packages Tessera builds with (and Xvfb with Mesa for the GUI tests;
# pybind11, Python's headers and numpy for the Python module; lld, which links three times as
# fast as GNU ld) (run as root, or with sudo available).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  cmake ninja-build g++ make lld \
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libtbb-dev libcli11-dev libfmt-dev nlohmann-json3-dev \
  qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-svg-dev libvtk9-dev fonts-dejavu-core \
  xvfb xauth libgl1-mesa-dri pybind11-dev python3-dev python3-numpy >/dev/null
echo "install-deps: done"
