#!/usr/bin/env bash
# The end of a background run is drawn without any input (issue 19, item 5): the test lab
# in a real window under Xvfb, `B` starts a run that ends while a frame is drawn; after it,
# a screenshot of the screen (nothing pressed, nothing moved) must show the ended state:
# the background turned green-blue and the triangle red, not the running yellow.
#   busy_end_window.sh TEST_LAB_EXE OUT.png
# Exits 77 (ctest SKIP_RETURN_CODE) without xvfb-run or ImageMagick's import.
set -uo pipefail
exe=$1 out=$2
command -v xvfb-run >/dev/null || { echo "xvfb-run not installed: skipped"; exit 77; }
command -v import >/dev/null || { echo "ImageMagick (import) not installed: skipped"; exit 77; }
rm -f "$out"
xvfb-run -a -s "-screen 0 1024x768x24" bash -c '
  "$1" --size 400x300 --keys Bh & pid=$!
  sleep 4
  import -window root "$2"
  kill $pid; wait $pid' _ "$exe" "$out"
[ -s "$out" ] || { echo "no screenshot"; exit 1; }
# Pixels of the window at the root's top-left (Xvfb has no window manager): the triangle
# covers the lower-left half of the scene, the background the upper-right.
triangle=$(convert "$out" -format '%[pixel:p{20,290}]' info:)
background=$(convert "$out" -format '%[pixel:p{780,10}]' info:)
echo "triangle $triangle, background $background"
case "$triangle" in *"255,0,0"*|red) ;; *) echo "the triangle does not show the ended run"; exit 1 ;; esac
case "$background" in *"0,128,255"*) ;; *) echo "the background does not show the ended run"; exit 1 ;; esac
