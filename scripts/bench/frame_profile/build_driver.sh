#!/bin/sh
# Builds the frame driver against the Release build's build/core/libcore.a (-g for callgrind's
# names), from the repository's root: scripts/bench/frame_profile/build_driver.sh
set -e
root="$(cd "$(dirname "$0")/../../.." && pwd)"
here="$root/scripts/bench/frame_profile"
c++ -O3 -DNDEBUG -g -std=c++17 -I"$root/core/include" "$here/frame_driver.cpp" -o "$here/frame_driver" \
  "$root/build/core/libcore.a" /usr/lib/x86_64-linux-gnu/libstb.so \
  /usr/lib/x86_64-linux-gnu/libtinyobjloader.so.2rc10 /usr/lib/x86_64-linux-gnu/libtbb.so.12.8
