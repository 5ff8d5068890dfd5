#!/bin/sh
# Builds the scratch frame driver against build/core/libcore.a (-g for callgrind's names).
cd "$(dirname "$0")" && c++ -O3 -DNDEBUG -g -std=c++17 -I../core/include frame_driver.cpp -o frame_driver \
  ../build/core/libcore.a /usr/lib/x86_64-linux-gnu/libstb.so /usr/lib/x86_64-linux-gnu/libtinyobjloader.so.2rc10 /usr/lib/x86_64-linux-gnu/libtbb.so.12.8
