#!/bin/sh
# drawn_crash_test.sh SOURCE_ROOT LAB01_HEADLESS WB_CHECK MUTANT_SO MUTANT_CPP WORKDIR
# (issue 18 item 3): student code that passes every check of lab 01 but crashes (mirror) or
# loops (shadow from a light at infinity) on the line the window draws. wb-check passes it;
# the lab, drawing it, stays up, says which task failed and why, and still writes its picture.
set -u
src=$1 lab=$2 checker=$3 so=$4 mutant=$5 work=$6
rm -rf "$work"
mkdir -p "$work/root/labs/01-affine"
# A root like the repository's, with the mutant as lab 01's exercise file (the lab compiles it
# when it is newer than the build's object, as after a student's save).
for f in "$src"/*; do
  [ "$(basename "$f")" = labs ] || ln -s "$f" "$work/root/$(basename "$f")"
done
for f in "$src"/labs/*; do
  [ "$(basename "$f")" = 01-affine ] || ln -s "$f" "$work/root/labs/$(basename "$f")"
done
for f in "$src"/labs/01-affine/*; do
  [ "$(basename "$f")" = exercises.cpp ] || ln -s "$f" "$work/root/labs/01-affine/$(basename "$f")"
done
cp "$mutant" "$work/root/labs/01-affine/exercises.cpp"
fail() { echo "FAIL: $*"; exit 1; }

out=$("$checker" lab01 --student "01=$so" 2>&1)
printf '%s\n' "$out"
printf '%s\n' "$out" | grep -q "grade" || fail "wb-check printed no grade"
[ "$(printf '%s\n' "$out" | grep -c '✓')" -eq 3 ] || fail "the mutant must pass all 3 checks"

# Mirror (the lab's first mode): SIGSEGV on the drawn line.
out=$("$lab" --root "$work/root" --keys e --out "$work/mirror.png" 2>&1); rc=$?
printf '%s\n' "$out"
[ $rc -eq 0 ] || fail "the lab exited $rc drawing a crashing mirror"
printf '%s\n' "$out" | grep -q "01.mirror: crashed on the drawn input: SIGSEGV" || fail "no crash report"
[ -s "$work/mirror.png" ] || fail "no picture"

# Shadow from a light at infinity (key 2): an endless loop on the drawn line.
out=$("$lab" --root "$work/root" --keys e2 --out "$work/loop.png" 2>&1); rc=$?
printf '%s\n' "$out"
[ $rc -eq 0 ] || fail "the lab exited $rc drawing a looping shadow"
printf '%s\n' "$out" | grep -q "01.shadow-dir: no answer within 2 s on the drawn input" || fail "no timeout report"
[ -s "$work/loop.png" ] || fail "no picture"
echo "ok"
