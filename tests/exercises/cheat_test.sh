#!/bin/sh
# cheat_test.sh ROOT BUILD_DIR pass|fail WORKDIR (issue 18 item 7): "cheats". Each
# tests/exercises/cheats/labNN*.cpp answers the tasks its "// cheats:" line names by calling
# the core functions that compute them, compiled in from core's own sources (#include
# "core/src/...", as a student could copy them). Each is built with the lab's own compile line
# (BUILD_DIR/exercises/labNN.compile, + ROOT and its core/include on the include path) and
# graded by BUILD_DIR's wb-check.
#   pass: ROOT is the repository: every cheated task must pass (the cheat reaches the answer);
#   fail: ROOT is a student handout: none may pass (it fails, throws at the cut body or is not
#         done). A task on the cheat's "// accepted:" line is a leak docs/exercises.md accepts:
#         reported, not failed (CHEATS_STRICT=1 fails it too). The cuts keep every declaration,
#         so a cheat that does not build proves nothing: it fails in both modes.
set -eu
root=$1 build=$2 want=$3 work=$4
mkdir -p "$work"
bad=0
for cheat in "$root"/tests/exercises/cheats/lab*.cpp; do
  name=$(basename "$cheat" .cpp)
  nn=$(printf '%s' "$name" | cut -c4-5)
  tasks=$(sed -n 's|^// cheats: ||p' "$cheat")
  accepted=$(sed -n 's|^// accepted: \([^ ]*\).*|\1|p' "$cheat")
  so=$work/cheat-$name.so out=$work/cheat-$name.txt
  # --gc-sections drops the parts of an included source the cheat does not call (and what they
  # need from core); --no-undefined makes a cheat that needs more of core than it includes fail
  # here, not silently at load time (not under a sanitizer: its runtime comes from the program
  # that loads the cheat).
  strict=-Wl,--no-undefined
  grep -q -- -fsanitize "$build/exercises/lab$nn.compile" && strict=
  sed "s|\"\\\$1\" -o \"\\\$2\"|-ffunction-sections -fdata-sections -Wl,--gc-sections $strict \"\$1\" -o \"\$2\"|" \
    "$build/exercises/lab$nn.compile" > "$work/compile-$name.sh"
  if ! CPLUS_INCLUDE_PATH=$root/core/include:$root sh "$work/compile-$name.sh" "$cheat" "$so" \
      > "$work/cheat-$name.log" 2>&1; then
    echo "FAIL: the cheat $name does not build: $(grep -m1 'error' "$work/cheat-$name.log" || true)"
    bad=1
    continue
  fi
  LC_ALL=C LANGUAGE=en "$build/bin/wb-check" "lab$nn" --student "$nn=$so" > "$out" 2>&1 || true
  for t in $tasks; do
    line=$(grep -F " $t " "$out" || true)
    if printf '%s' "$line" | grep -q "✓"; then passed=yes; else passed=no; fi
    echo "cheat $t: ${line:-no line (the object did not load: $(grep -m1 -i 'cannot load' "$out" || true))}"
    if [ "$want" = pass ] && [ $passed = no ]; then
      echo "FAIL: the cheat for $t does not pass here: it is no test of the handout"; bad=1
    fi
    if [ "$want" = fail ] && [ $passed = yes ]; then
      if [ "$t" = "$accepted" ] && [ -z "${CHEATS_STRICT:-}" ]; then
        echo "  accepted (docs/exercises.md): $t passes in a handout"
      else
        echo "FAIL: $t passes by calling the function that computed the answer: the answer is in the handout"
        bad=1
      fi
    fi
  done
done
[ $bad -eq 0 ] && echo "cheats: as expected ($want)"
exit $bad
