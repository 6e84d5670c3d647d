#!/usr/bin/env bash
# Installs what shotlab needs to build, run and test on Debian 12 (as root, or with sudo available).
set -euo pipefail
packages=(
  cmake g++ make pkg-config git
  libboost-dev libglm-dev nlohmann-json3-dev libcli11-dev          # engine, scene files, command line
  libglfw3-dev libgl-dev libimgui-dev libstb-dev                   # GUI (GLFW, OpenGL 3.3, Dear ImGui, PNG)
  fonts-dejavu-core                                                # the GUI's font
  libgtest-dev libbenchmark-dev xvfb xauth python3                 # tests, micro benchmarks, GUI test display
  xdotool x11-apps                                                 # real mouse and keys, screen grabs (GUI test)
  python3-matplotlib                                               # the bench's figures (scripts/bench_plots.py)
  valgrind                                                         # instruction counts (scripts/speed_bench.py)
  pybind11-dev python3-dev python3-numpy python3-pytest            # the Python module and its tests
  python3-distributed                                              # sweeps on a Dask cluster (shotlab.cluster)
  libceres-dev                                                     # calibration against measured shots (shotlab fit)
)
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
