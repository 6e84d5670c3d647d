#!/usr/bin/env bash
# Builds and runs every test: engine, stability suite and GUI test (ctest; the GUI test starts its own Xvfb), a quick
# work-precision bench, then the engine, stability and app tests once more under AddressSanitizer and UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
(cd build && ctest --output-on-failure -j2)
./build/app/shotlab bench --quick --out-dir build/bench-quick
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHOTLAB_SANITIZE=ON -DSHOTLAB_GUI=OFF \
      -DSHOTLAB_TESTS=ON > /dev/null
cmake --build build-asan -j"$(nproc)" --target engine_tests stability_tests app_tests shotlab shotlab_c \
      capi_dlopen_test
(cd build-asan && ctest --output-on-failure -j2 -L 'engine|stability|app')
