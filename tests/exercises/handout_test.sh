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

# Labs 06-08 (docs/exercises.md, "Labs 06-08 in a handout"): no cheat that compiles in core's
# own code for a task's answer passes, and none of the answers' distinctive expressions is left.
"$work/clone/tests/exercises/handout_cheats.sh" "$h" "$BUILD_DIR" "$work/cheats" ||
  { echo "FAIL: an answer of labs 06-08 is still in the handout"; exit 1; }
if grep -rn "4.0 / 3.0 \* std::tan\|hemisphere({3, 1, 2, 3, 5})\|V \* cosI \* cosJ\|p.emission + p.reflectivity \* FB_\[static_cast<std::size_t>(i)\];$\|Color bd = mulBy(mul(bl, c), fd)\|(radius - ll) \* (radius + ll)\|copysign(std::sqrt(disc), h)\|e - 2 \* glm::dot(e, n) \* n" \
     "$h/core" "$h/labs"; then echo "FAIL: an answer's expression of labs 06-08 is in the handout"; exit 1; fi
cmake --build "$BUILD_DIR" -j 2 --target lab06-bezier-headless lab07-raytrace-headless lab08-radiosity-headless > "$work/labs68.txt" 2>&1 ||
  { cat "$work/labs68.txt"; echo "FAIL: labs 06-08 do not build in the handout"; exit 1; }
for lab in lab06-bezier lab07-raytrace lab08-radiosity; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-stubs.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done

# The labs with exercises build in it and draw (headless) with the stubs: no reference, no crash.
cmake --build "$BUILD_DIR" -j 2 --target lab01-affine-headless lab02-lighting-headless > "$work/labs.txt" 2>&1 ||
  { cat "$work/labs.txt"; echo "FAIL: the handout's labs do not build"; exit 1; }
for lab in lab01-affine lab02-lighting; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-stubs.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done

# The reference answers pasted over the stubs (as a student who solved everything).
for d in "$repo"/labs/*/; do
  [ -f "$d/exercises_reference.cpp" ] || continue
  cp "$d/exercises_reference.cpp" "$h/labs/$(basename "$d")/exercises.cpp"
done
(cd "$h" && ./wb check) > "$work/reference.txt" 2>&1 || { cat "$work/reference.txt"; echo "FAIL: the references must pass"; exit 1; }
cat "$work/reference.txt"
for lab in lab01-affine lab02-lighting; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-answers.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done
for lab in lab06-bezier lab07-raytrace lab08-radiosity; do
  "$BUILD_DIR/bin/$lab-headless" --out "$work/$lab-answers.png" || { echo "FAIL: $lab in the handout"; exit 1; }
done
if grep -q "✗\|not done" "$work/reference.txt"; then echo "FAIL: not every task passes"; exit 1; fi
labs=$(grep -c "grade:" "$work/reference.txt")
fives=$(grep -c "grade: ⑤" "$work/reference.txt")
[ "$labs" -eq "$fives" ] || { echo "FAIL: grade 5 in $fives of $labs labs"; exit 1; }
echo "handout OK: $labs labs, grade 5 in each with the references"
