#!/usr/bin/env bash
# Issue 19 item 12: lab 08's Cornell box against Blender's Cycles, per surface (a bench, not a
# CI test: blender is no CI dependency). Prints the Markdown table of docs/bench/radiosity.md.
#   scripts/bench/radiosity_reference.sh [BUILD_DIR] [OUT_DIR]
# ~10 min on a quiet 2-core machine (most of it our fine setting and 2 Cycles runs).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
out=${2:-$build/bench-out/radiosity-reference}
mkdir -p "$out"
"$root/scripts/setup.sh" blender
cmake --build "$build" --target radiosity_reference radiosity_mc >/dev/null
"$build/bin/radiosity_reference" --out "$out/ours.json"
# A second independent estimate: brute-force Monte Carlo path tracing on the exact polygons
# (tests/bench/radiosity_mc.cpp; ~4 min on a quiet machine).
"$build/bin/radiosity_mc" --paths 4000000 --batches 8 --out "$out/mc.json"
py="$root/scripts/bench/radiosity_reference.py"
# Two independent reference runs (Cycles bakes each face): 32² texels × 128 samples × 4 seeds
# (the reference and its noise: std. error over the seeds) and 24² × 256 × 2 (checks that
# neither the sample count nor the texel size moves the answer beyond that noise).
blender -b --factory-startup --python "$py" -- "$out/ours.json" "$out/ref_a.json" --samples 128 --seeds 4 --pixels 32 | grep -E '^REF|^wrote'
blender -b --factory-startup --python "$py" -- "$out/ours.json" "$out/ref_b.json" --samples 256 --seeds 2 --pixels 24 | grep -E '^REF|^wrote'
python3 "$root/scripts/bench/radiosity_reference_table.py" --mc "$out/mc.json" "$out/ours.json" "$out/ref_a.json" "$out/ref_b.json"
