#!/bin/sh
# Usage: run_gui_test.sh SHOTLAB_BINARY TEST_SOURCE_DIR
# Runs the GUI under a private Xvfb (CI has no display), in a scratch directory that receives the script's dumps,
# screenshots and CSV, then checks them.
set -eu
shotlab=$1
here=$2
out=$(mktemp -d)
display=:97
Xvfb $display -screen 0 1280x720x24 -nolisten tcp >"$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
for _ in 1 2 3 4 5 6 7 8 9 10; do  # wait for the server socket
  [ -e /tmp/.X11-unix/X97 ] && break
  sleep 0.3
done
cp "$here/bad_scene.json" "$out/"
cd "$out"
DISPLAY=$display timeout 90 "$shotlab" --script "$here/smoke.script" --width 1280 --height 720
python3 "$here/check.py" "$out"
rm -rf "$out"  # kept when a check fails (set -e), for a look
