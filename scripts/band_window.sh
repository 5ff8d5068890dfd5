#!/usr/bin/env bash
# A scene area taller than 4:3 gets the scene at its bottom and the band above it in the
# lab's background (issue 19): lab 07's traced view (G) in a window whose scene area is
# 480x480 (--size) shows its 480x360 image at the bottom; the 120-px band above it must be
# the scene's sky, not the black it was. Pixels of a root-window screenshot (no window
# manager: the window is at 0,0).
#   band_window.sh LAB07_EXE OUT.png
# Exits 77 (ctest SKIP_RETURN_CODE) without xvfb-run or ImageMagick.
set -uo pipefail
exe=$1 out=$2
command -v xvfb-run >/dev/null || { echo "xvfb-run not installed: skipped"; exit 77; }
command -v import >/dev/null || { echo "ImageMagick (import) not installed: skipped"; exit 77; }
rm -f "$out"
xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
  "$1" --size 480x480 --keys G & pid=$!
  sleep 6
  import -window root "$2"
  kill $pid; wait $pid' _ "$exe" "$out"
[ -s "$out" ] || { echo "no screenshot"; exit 1; }
px() { convert "$out" -format "%[pixel:p{$1,$2}]" info:; }
band=$(px 240 20) sky=$(px 240 125) # in the band; the traced image's top row (sky)
echo "band (240,20): $band; traced sky (240,125): $sky"
[[ "$band" =~ ^(srgb\(0,0,0\)|black)$ ]] && { echo "the band above the scene is black"; exit 1; }
[ "$band" = "$sky" ] || { echo "the band is not the scene's background"; exit 1; }
exit 0
