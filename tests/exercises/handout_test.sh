#!/bin/sh
# handout_test.sh REPO CHECKER WORKDIR (issue 18 item 7): a handout made from a fresh clone of
# REPO at its HEAD builds on its own; ./wb check in it says every task is not done with the
# stubs, and every task passes (grade 5 everywhere) with the reference answers pasted in.
set -eu
repo=$1 checker=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
sha=$(git -C "$repo" rev-parse HEAD)
git clone -q --no-checkout "$repo" "$work/clone"
git -C "$work/clone" checkout -q "$sha"
WB_CHECK=$checker "$work/clone/scripts/handout.sh" "$work/handout"
h=$work/handout

# No answers in it: no mutants, no reference table, no answer code left in the stripped files.
if grep -l "WB_MUTANT(" "$h"/labs/[0-9]*/*.cpp || grep -l "WB_EXERCISE_TABLE(" "$h"/labs/*/exercises_reference.cpp; then echo "FAIL: mutant/reference code in the handout"; exit 1; fi
if grep -q "outerProduct\|2.0 \* n" "$h/core/src/affine.cpp" 2>/dev/null && \
   grep -A8 "^glm::dmat3 mirrorLine" "$h/core/src/affine.cpp" | grep -q "requireNormal"; then
  echo "FAIL: core's mirrorLine is still in the handout"; exit 1
fi
grep -q "^labs/" "$h/labs/handout_expected.tsv" && { echo "FAIL: bad recording"; exit 1; }
# The answers of every lab, by their distinctive expressions (each is in
# the repository: tests/exercises/handout_answers.txt says where), in no source, catalogue,
# page or recording of the handout.
found=0
while IFS= read -r pat; do
  case $pat in ''|'#'*) continue ;; esac
  # A pattern the repository no longer has would find nothing anywhere: a check that cannot fail.
  grep -rqE -- "$pat" "$work/clone/core" "$work/clone/labs" ||
    { echo "FAIL: stale pattern (not in the repository's core/ or labs/): $pat"; found=1; }
  if grep -rnE -- "$pat" "$h/core" "$h/labs" "$h/i18n" "$h/docs"; then
    echo "FAIL: an answer is in the handout: $pat"; found=1
  fi
done < "$repo/tests/exercises/handout_answers.txt"
[ $found -eq 0 ] || exit 1
# The recording holds only what the checks need: no mesh of lab 04 (its area only).
if grep -E "^04\.(sphere|torus)	" "$h/labs/handout_expected.tsv" | awk -F'\t' 'NF > 3 { exit 1 }'; then :; else
  echo "FAIL: lab 04's meshes are recorded in the handout"; exit 1
fi

# Built on its own, with the README's command (ccache keyed on this fixed work dir).
export CCACHE_BASEDIR=$work
export BUILD_DIR=$h/build CMAKE_ARGS="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache"
export JOBS=2
set +e
(cd "$h" && ./wb check) > "$work/stubs.txt" 2>&1
rc=$?
set -e
cat "$work/stubs.txt"
[ $rc -ne 0 ] || { echo "FAIL: the stubs must exit non-zero"; exit 1; }
grep -q "Nothing attempted yet" "$work/stubs.txt" || { echo "FAIL: stubs not all not done"; exit 1; }
if grep -q "✓\|✗" "$work/stubs.txt"; then echo "FAIL: a stub passed or failed"; exit 1; fi

# Cheats: tasks answered by calling the core functions that computed them must not pass here
# (tests/exercises/cheats, every lab; the same cheats pass in the repository, a ctest there
# says so).
sh "$h/tests/exercises/cheat_test.sh" "$h" "$BUILD_DIR" fail "$work/cheats" ||
  { echo "FAIL: an answer is still callable in the handout"; exit 1; }

# The labs with exercises build in it and draw (headless) with the stubs: no reference, no crash.
# Every lab with exercises (labs/NN-name/exercises.cpp -> target labNN-name-headless).
labs=$(for d in "$h"/labs/[0-9]*/exercises.cpp; do n=$(basename "$(dirname "$d")"); echo "lab$n"; done)
# shellcheck disable=SC2046
cmake --build "$BUILD_DIR" -j 2 --target $(for l in $labs; do echo "$l-headless"; done) > "$work/labs.txt" 2>&1 ||
  { cat "$work/labs.txt"; echo "FAIL: the handout's labs do not build"; exit 1; }
for lab in $labs; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-stubs.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done

# The reference answers pasted over the stubs (as a student who solved everything).
for d in "$repo"/labs/*/; do
  [ -f "$d/exercises_reference.cpp" ] || continue
  cp "$d/exercises_reference.cpp" "$h/labs/$(basename "$d")/exercises.cpp"
done
(cd "$h" && ./wb check) > "$work/reference.txt" 2>&1 || { cat "$work/reference.txt"; echo "FAIL: the references must pass"; exit 1; }
cat "$work/reference.txt"
for lab in $labs; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-answers.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done
if grep -q "✗\|not done" "$work/reference.txt"; then echo "FAIL: not every task passes"; exit 1; fi
nlabs=$(grep -c "grade:" "$work/reference.txt")
fives=$(grep -c "grade: ⑤" "$work/reference.txt")
[ "$nlabs" -eq "$fives" ] || { echo "FAIL: grade 5 in $fives of $nlabs labs"; exit 1; }
echo "handout OK: $nlabs labs, grade 5 in each with the references"
