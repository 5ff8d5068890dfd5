#!/usr/bin/env bash
# The .deb works without a source tree (issue 19, item 6): cpack makes it from the build,
# dpkg-deb -x unpacks it into a temporary root, and there, with WORKBENCH_ROOT unset and the
# source and build trees hidden (empty tmpfs mounted over them in a private mount
# namespace), every lab renders headless through its window executable (which starts its
# -headless twin), and the launcher renders them all.
#   package_test.sh BUILD_DIR SOURCE_DIR
# Exits 77 (ctest SKIP_RETURN_CODE) when cpack/dpkg-deb are missing or the trees cannot be
# hidden (unshare needs root or user namespaces).
set -uo pipefail
build=$(realpath "$1") src=$(realpath "$2")
for tool in cpack dpkg-deb dpkg-shlibdeps unshare; do
  command -v $tool >/dev/null || { echo "$tool not installed: skipped"; exit 77; }
done
unshare -m true 2>/dev/null || { echo "cannot make a mount namespace: skipped"; exit 77; }
tmp=$(mktemp -d /tmp/wb-package.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
if ! cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp" >"$tmp/cpack.log" 2>&1; then
  cat "$tmp/cpack.log"; echo "cpack failed"; exit 1
fi
deb=$(ls "$tmp"/*.deb)
echo "package: $deb ($(du -h "$deb" | cut -f1))"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libglut libglew libosmesa6 libtbb libstb fonts-dejavu-core; do
  case "$depends" in *"$lib"*) ;; *) echo "Depends lacks $lib"; exit 1 ;; esac
done
dpkg-deb -x "$deb" "$tmp/root"
bin=$tmp/root/usr/bin
[ -x "$bin/workbench" ] || { echo "no /usr/bin/workbench in the package"; exit 1; }
[ -f "$tmp/root/usr/share/workbench/shaders/phong.frag" ] || { echo "no shaders in /usr/share/workbench"; exit 1; }
mkdir -p "$tmp/out"
# Inside the namespace the source and build trees are empty folders.
unshare -m bash -s "$src" "$build" "$bin" "$tmp/out" <<'INNER'
set -uo pipefail
src=$1 build=$2 bin=$3 out=$4
mount -t tmpfs none "$src" || exit 1
if [ -n "$(ls -A "$build" 2>/dev/null)" ]; then mount -t tmpfs none "$build" || exit 1; fi
[ -z "$(ls -A "$src")" ] || { echo "the source tree is still visible"; exit 1; }
unset WORKBENCH_ROOT DISPLAY
export ASAN_OPTIONS=detect_leaks=0
failed=0
for exe in "$bin"/*-headless; do
  lab=$(basename "$exe" -headless)
  "$bin/$lab" --headless --out "$out/$lab.png" --size 160x120 >"$out/$lab.log" 2>&1
  rc=$?
  if [ $rc -ne 0 ] || [ ! -s "$out/$lab.png" ] || grep -qiE "cannot |not found|no such file" "$out/$lab.log"; then
    echo "$lab: FAILED (exit $rc)"; cat "$out/$lab.log"; failed=1
  else
    echo "$lab: ok from $bin (no source tree)"
  fi
done
"$bin/workbench" --headless --out-dir "$out/all" --size 80x60 || failed=1
exit $failed
INNER
