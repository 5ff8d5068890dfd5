#!/usr/bin/env bash
# The end of a background run is drawn without any input (issue 19, item 5): the test lab
# in a real window under Xvfb, `B` starts a run that ends while a frame is drawn; after it,
# a screenshot of the screen (nothing pressed, nothing moved) must show the ended state:
# the background turned green-blue and the triangle red, not the running yellow.
#   busy_end_window.sh TEST_LAB_EXE OUT.png
# Exits 77 (ctest SKIP_RETURN_CODE) without xvfb-run or ImageMagick's import.
set -uo pipefail
. "$(dirname "$0")/lib/window.sh"
exe=$1 out=$2
need_window_tools
window_shot 1024x768 4 "$out" "$exe" --size 400x300 --keys Bh
# The triangle covers the lower-left half of the scene, the background the upper-right.
triangle=$(pixel "$out" 20 290) background=$(pixel "$out" 780 10)
echo "triangle $triangle, background $background"
case "$triangle" in *"255,0,0"*|red) ;; *) echo "the triangle does not show the ended run"; exit 1 ;; esac
case "$background" in *"0,128,255"*) ;; *) echo "the background does not show the ended run"; exit 1 ;; esac
