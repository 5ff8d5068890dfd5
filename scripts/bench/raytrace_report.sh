#!/bin/sh
# One command for the ray tracer bench report (issue 21): docs/bench/raytrace.md, its CSV and
# plot, with the Embree tables and the goals table of issue 21. Configures BUILD_DIR (default
# build-bench: Release, -DWORKBENCH_EMBREE=ON, ccache if present), builds raytrace_scale_bench,
# and runs it between two `uptime`s (also written to BUILD_DIR/raytrace_report.log). Arguments
# go to the bench (e.g. --runs 3). Needs libembree-dev and gnuplot-nox (scripts/setup.sh).
# About 4.5 minutes of bench on the 2-core machine at load 8–13 (20:12 UTC, 1 Dec 2026), plus the build.
set -eu
"$(dirname "$0")/../setup.sh" libembree-dev gnuplot-nox
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
launcher=""
if command -v ccache >/dev/null 2>&1; then
    launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache"
fi
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DWORKBENCH_EMBREE=ON $launcher >/dev/null
cmake --build "$build" -j2 --target raytrace_scale_bench
log="$build/raytrace_report.log"
{
    echo "start: $(date -u '+%F %T UTC') $(uptime)"
    start=$(date +%s)
    "$build/bin/raytrace_scale_bench" --out-dir "$root/docs/bench" "$@" >/dev/null
    echo "end:   $(date -u '+%F %T UTC') $(uptime)"
    echo "bench wall time: $(( $(date +%s) - start )) s"
} 2>&1 | tee "$log"
echo "wrote $root/docs/bench/raytrace.md (log: $log)"
