#!/usr/bin/env bash
# Configures and builds shotlab (Release, GUI and tests) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHOTLAB_GUI=ON -DSHOTLAB_TESTS=ON > /dev/null
cmake --build build -j"$(nproc)"
