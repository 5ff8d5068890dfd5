#!/usr/bin/env bash
# A scene area taller than 4:3 gets the scene at its bottom and the band above it in the
# lab's background (issue 19): lab 07's traced view (G) in a window whose scene area is
# 480x480 (--size) shows its 480x360 image at the bottom; the 120-px band above it must be
# the scene's sky, not the black it was. Under the heat map (G then d) the band is black, the
# map's "no difference", not the sky (it read as part of the map).
#   band_window.sh LAB07_EXE OUT.png
# Exits 77 (ctest SKIP_RETURN_CODE) without xvfb-run or ImageMagick.
set -uo pipefail
. "$(dirname "$0")/lib/window.sh"
exe=$1 out=$2
need_window_tools
window_shot 1280x800 6 "$out" "$exe" --size 480x480 --keys G
band=$(pixel "$out" 240 20) sky=$(pixel "$out" 240 125) # in the band; the traced image's top row (sky)
echo "band (240,20): $band; traced sky (240,125): $sky"
[[ "$band" =~ ^(srgb\(0,0,0\)|black)$ ]] && { echo "the band above the scene is black"; exit 1; }
[ "$band" = "$sky" ] || { echo "the band is not the scene's background"; exit 1; }
heat=${out%.png}-heat.png
window_shot 1280x800 8 "$heat" "$exe" --size 480x480 --keys Gd
band=$(pixel "$heat" 240 20) top=$(pixel "$heat" 240 125) # the band; the map's top row (sky = sky)
echo "heat map: band (240,20): $band; map's top row (240,125): $top"
[[ "$band" =~ ^(srgb\(0,0,0\)|black)$ ]] || { echo "the band above the heat map is not black"; exit 1; }
[ "$band" = "$top" ] || { echo "the band is not the heat map's zero"; exit 1; }
exit 0
