# Shared by the real-window tests (scripts/*_window.sh); sourced, not run. A lab in a fresh
# Xvfb with no window manager, so its window sits at the root's top-left and a root-window
# screenshot's pixels are the window's.

# need_window_tools: exit 77 (ctest's SKIP_RETURN_CODE) without xvfb-run or ImageMagick.
need_window_tools() {
  command -v xvfb-run >/dev/null || { echo "xvfb-run not installed: skipped"; exit 77; }
  command -v import >/dev/null || { echo "ImageMagick (import) not installed: skipped"; exit 77; }
}

# window_shot SCREEN SECONDS OUT EXE [ARGS...]: runs EXE ARGS on a SCREEN-sized (WxH) Xvfb,
# screenshots the root window into OUT after SECONDS with nothing pressed or moved, stops EXE.
window_shot() {
  local screen=$1 wait=$2 out=$3
  shift 3
  rm -f "$out"
  xvfb-run -a -s "-screen 0 ${screen}x24" bash -c '
    wait_s=$1 shot=$2; shift 2
    "$@" & pid=$!
    sleep "$wait_s"
    import -window root "$shot"
    kill $pid; wait $pid' _ "$wait" "$out" "$@"
  [ -s "$out" ] || { echo "no screenshot"; exit 1; }
}

# pixel PNG X Y: the colour of one pixel as ImageMagick writes it (e.g. srgb(255,0,0) or red).
pixel() { convert "$1" -format "%[pixel:p{$2,$3}]" info:; }
