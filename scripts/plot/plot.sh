#!/usr/bin/env bash
# Draws a bench plot with gnuplot: scripts/plot/NAME.gp reads DIR/NAME*.csv (written by the
# bench program) and writes DIR/NAME.png. Usage: scripts/plot/plot.sh NAME [DIR]
# (DIR defaults to docs/bench). Only the bench reports need gnuplot, not the tests: when it
# is missing, scripts/setup.sh installs gnuplot-nox (Debian) first.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
name="${1:?usage: $0 NAME [DIR]  (scripts/plot/NAME.gp)}"
dir="${2:-$root/docs/bench}"
script="$here/$name.gp"
[ -f "$script" ] || { echo "$0: no plot script $script" >&2; exit 2; }
ls "$dir/$name"*.csv >/dev/null 2>&1 || { echo "$0: no $dir/$name*.csv (run the bench first)" >&2; exit 2; }
command -v gnuplot >/dev/null || "$root/scripts/setup.sh" gnuplot-nox
gnuplot -e "dir='$dir'; out='$dir/$name.png'; dir_scripts='$here'" "$script"
echo "wrote $dir/$name.png" >&2
