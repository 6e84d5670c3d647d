#!/usr/bin/env bash
# cmake --install into a scratch prefix, then build tests/capi/example.c the way docs/c-api.md says (pkg-config) and
# with the CMake package, and run both on a preset: a user's program against the installed library; then the
# installed Python package.
# usage: install_check.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 src=$(cd "$2" && pwd)
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
libdir=$(dirname "$(find "$prefix" -name shotlab.pc)")
export PKG_CONFIG_PATH=$libdir
# shellcheck disable=SC2046
cc -std=c99 -Wall -o "$prefix/example" "$src/tests/capi/example.c" $(pkg-config --cflags --libs shotlab) \
   -Wl,-rpath,"$(pkg-config --variable=libdir shotlab)"
out=$("$prefix/example" "$src/presets/cut.json")
echo "$out"
grep -q "pocketed: 1" <<< "$out" || { echo "FAIL: the cut shot pots the 1 ball through the installed library"; exit 1; }
# The CMake package: find_package(shotlab) and link shotlab::shotlab.
mkdir -p "$prefix/user"
cat > "$prefix/user/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(user C)
find_package(shotlab 0.1 REQUIRED)
add_executable(example $src/tests/capi/example.c)
target_link_libraries(example PRIVATE shotlab::shotlab)
CMAKE
cmake -S "$prefix/user" -B "$prefix/user/build" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$prefix/user/build" > /dev/null
"$prefix/user/build/example" "$src/presets/cut.json" | grep -q "pocketed: 1" || { echo "FAIL: the CMake package"; exit 1; }
echo "installed library: pkg-config and CMake package builds pot the 1 ball"
# The Python package from the prefix, as docs/python.md says (when the build made it).
if [ -d "$build/python/shotlab" ]; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import shotlab
assert shotlab.__file__.startswith('$prefix'), shotlab.__file__
rows = shotlab.sweep('$src/presets/cut.json', ['cue.speed=2'])
assert rows[0]['pocketed'] == '1@pocket-right-front', rows
import shotlab.cluster
" || { echo "FAIL: the installed Python package"; exit 1; }
  echo "installed Python package: imports and its sweep pots the 1 ball"
fi
