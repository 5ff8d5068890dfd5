#!/usr/bin/env bash
# Installs the Debian packages the workbench needs, only those missing.
# Non-interactive and idempotent; needs root (or sudo) when something is missing.
set -euo pipefail

pkgs=(
  cmake g++ make pkg-config
  freeglut3-dev libglew-dev libglm-dev libimgui-dev catch2
  libosmesa6-dev libglu1-mesa-dev libstb-dev libtinyobjloader-dev libtbb-dev
  libcli11-dev fonts-dejavu-core libeigen3-dev libcgal-dev
  xvfb xauth imagemagick dpkg-dev
  gettext libx11-dev libxkbcommon-dev x11-xkb-utils xdotool
)
# Extra packages asked for by the caller (e.g. CI wants clang for the fuzzers; the bench
# plots' scripts/plot/plot.sh asks for gnuplot-nox, scripts/bench/radiosity_reference.sh for
# blender - the tests need neither).
pkgs+=("$@")

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q >/dev/null
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
