#!/usr/bin/env bash
# Smoke run of one executable in a real window under Xvfb: it draws some frames,
# replays keys, saves a screenshot; the run must exit 0 and the screenshot must not be blank.
#   smoke_window.sh PNG_STATS OUT.png MIN_COLOURS EXE [ARGS...]
# Exits 77 (ctest SKIP_RETURN_CODE) when xvfb-run is not installed.
set -uo pipefail
stats=$1 out=$2 minColours=$3
shift 3
command -v xvfb-run >/dev/null || { echo "xvfb-run not installed: skipped"; exit 77; }
rm -f "$out"
# -a picks a free display number, so smoke tests can run in parallel.
xvfb-run -a -s "-screen 0 1024x768x24" timeout 120 "$@" --screenshot "$out"
rc=$?
if [ $rc -ne 0 ]; then
  echo "smoke: $1 exited with $rc"
  exit 1
fi
[ -s "$out" ] || { echo "smoke: no screenshot written"; exit 1; }
"$stats" "$out" --min-colours "$minColours"
