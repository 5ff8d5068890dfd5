#!/bin/sh
# cheat_test.sh ROOT BUILD_DIR pass|fail WORKDIR (issue 18 item 7): the cheats in
# tests/exercises/cheats/labNN.cpp answer tasks by calling the core functions that compute
# them (their "// cheats:" line names the tasks). Each is built the way the lab builds a
# student's file (BUILD_DIR/exercises/labNN.compile, with core's headers on the path so it
# can compile core's sources in) and graded by BUILD_DIR's wb-check.
#   pass: in the repository every cheated task must pass (the cheat is a real one);
#   fail: in a student handout none may pass (the answers are not in it): it fails, is not
#         done, or the cheat does not even build or load.
set -eu
root=$1 build=$2 want=$3 work=$4
mkdir -p "$work"
bad=0
for cheat in "$root"/tests/exercises/cheats/lab*.cpp; do
  nn=$(basename "$cheat" .cpp | cut -c4-5)
  tasks=$(sed -n 's|^// cheats: ||p' "$cheat")
  so=$work/cheat-lab$nn.so
  out=$work/cheat-lab$nn.txt
  if ! CPLUS_INCLUDE_PATH=$root/core/include sh "$build/exercises/lab$nn.compile" "$cheat" "$so" \
      > "$work/cheat-lab$nn.log" 2>&1; then
    if [ "$want" = pass ]; then
      cat "$work/cheat-lab$nn.log"; echo "FAIL: the lab $nn cheat does not build"; bad=1
    else
      echo "cheat lab$nn: does not build ($(head -c 200 "$work/cheat-lab$nn.log"))"
    fi
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
      echo "FAIL: $t passes by calling the function that computed the answer: the answer is in the handout"
      bad=1
    fi
  done
done
[ $bad -eq 0 ] && echo "cheats: as expected ($want)"
exit $bad
