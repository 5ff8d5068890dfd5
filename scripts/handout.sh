#!/usr/bin/env bash
# ./wb handout DIR (issue 18 item 7): writes a copy of the workbench to give to students.
# - the files committed at HEAD (git archive: local edits, build dirs and history stay out),
#   so every labs/NN-name/exercises.cpp is the stub the repository ships;
# - labs/handout_expected.tsv: the outputs of the reference answers on every check's cases,
#   recorded now; the handout's checks compare with them (CMake sees the file and builds in
#   handout mode: WB_HANDOUT);
# - no reference answers: each exercises_reference.cpp becomes an empty reference, and the
#   answers that live in shared code (labs/handout_strip.txt: core's 2D mirror and shadow
#   matrices, lab 02's cube) are cut (scripts/handout_strip.py);
# - tests/: only the exercises' tests (the others check the answers).
# WB_CHECK=path/to/wb-check records with that checker instead of building one in BUILD_DIR.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: ./wb handout DIR}
build=${BUILD_DIR:-$here/build}
if [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then
  echo "handout: $out exists and is not empty" >&2
  exit 2
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)

git -C "$here" archive HEAD | tar -x -C "$out"

checker=${WB_CHECK:-}
if [ -z "$checker" ]; then
  # shellcheck disable=SC2086
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} ${CMAKE_ARGS:-} >/dev/null
  cmake --build "$build" -j "${JOBS:-$(nproc)}" --target wb-check >/dev/null
  checker=$build/bin/wb-check
fi
"$checker" --record "$out/labs/handout_expected.tsv"

for f in "$out"/labs/*/exercises_reference.cpp; do
  nn=$(basename "$(dirname "$f")" | cut -c1-2)
  cat > "$f" <<REF
// Not in the handout: the checks compare with labs/handout_expected.tsv, recorded from the
// reference answers when the handout was made.
const void* wbExerciseReference_lab$nn();
const void* wbExerciseReference_lab$nn() {
    return nullptr;
}
REF
done
python3 "$here/scripts/handout_strip.py" "$out" "$here/labs/handout_strip.txt"
rm -rf "$out"/tests/{core,render,golden,bench,fuzz,shell,tools}
# The handout test itself and its list of the answers' expressions (which quotes them).
rm -f "$out"/tests/exercises/handout_test.sh "$out"/tests/exercises/handout_answers.txt

echo "handout written to $out:"
echo "  the students run ./wb run and ./wb check there; their files are labs/*/exercises.cpp"
