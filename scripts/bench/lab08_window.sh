#!/usr/bin/env bash
# Lab 08's defaults in a real window against headless (issue 19 item 7; docs/bench/radiosity.md
# "Lab 08 defaults"): for each round and method (rays, CPU hemicube, GL hemicube), alternated:
# the headless run, then a window of each lab08-radiosity given (e.g. a build before and after
# a change). A window run is timed by the lines the lab prints ("unshot power < 5% after",
# "run X s (solving Y s)"; since l08fast also "usable picture drawn after": the frame that first
# shows it, empty for a build without that line), with the CPU seconds of the lab process up to convergence; with
# WB_FRAME_LOG=1 the shell adds where the run's frames spent their time. Needs an X display
# (DISPLAY, e.g. Xvfb 1280x800). Not a CI test: timings on a shared machine.
#   lab08_window.sh ROUNDS HEADLESS_EXE WINDOW_EXE [WINDOW_EXE...]
set -uo pipefail
rounds=$1 headless=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cpu() { awk '{printf "%.2f", ($14+$15)/100}' "/proc/$1/stat"; }
window() { # exe method
    local out t0 t1 c1 pid
    out=$(mktemp "$tmp/window.XXXX") # empty before the lab starts: no line of an earlier run
    t0=$(date +%s.%N)
    WB_FRAME_LOG=1 "$1" --method "$2" >"$out" 2>&1 &
    pid=$!
    for _ in $(seq 1 3000); do
        grep -q "residual" "$out" && break
        sleep 0.02
    done
    t1=$(date +%s.%N)
    c1=$(cpu $pid)
    sleep 0.5 # the frame after the run (and its frame log line)
    kill $pid 2>/dev/null
    wait $pid 2>/dev/null
    printf "window %s %s: usable %s s (drawn %s s), converged %s s, from launch %.2f s, CPU %s s | %s\n" \
        "$2" "$1" "$(grep -o 'after [0-9.]* s' "$out" | head -1 | awk '{print $2}')" \
        "$(grep -o 'drawn after [0-9.]* s' "$out" | head -1 | awk '{print $3}')" \
        "$(grep -o 'run [0-9.]* s' "$out" | head -1 | awk '{print $2}')" \
        "$(echo "$t1 - $t0" | bc)" "$c1" "$(grep '^frames' "$out" | head -1)"
}
for r in $(seq 1 "$rounds"); do
    for m in rays cpu gl; do
        echo "round $r, $(uptime | sed 's/.*load/load/')"
        /usr/bin/time -f "%U %S %e" "$headless" --method $m --out "$tmp/h.png" >"$tmp/h.txt" 2>&1
        printf "headless %s: converged %s s, CPU %s s\n" $m \
            "$(grep -o 'last run [0-9.]* s' "$tmp/h.txt" | awk '{print $3}')" \
            "$(tail -1 "$tmp/h.txt" | awk '{print $1 + $2}')"
        for exe in "$@"; do window "$exe" $m; done
    done
done
