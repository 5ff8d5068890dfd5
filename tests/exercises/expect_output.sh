#!/bin/sh
# expect_output.sh EXPECTED_EXIT PATTERN_FILE -- COMMAND...: runs COMMAND, and fails unless
# it exits with EXPECTED_EXIT ("nonzero" for any failure) and its output matches every line
# (a grep -E pattern) of PATTERN_FILE.
want=$1; patterns=$2; shift 3
out=$("$@" 2>&1); rc=$?
printf '%s\n' "$out"
if [ "$want" = nonzero ]; then
  [ $rc -ne 0 ] || { echo "expected a non-zero exit, got 0"; exit 1; }
else
  [ $rc -eq "$want" ] || { echo "expected exit $want, got $rc"; exit 1; }
fi
while IFS= read -r p; do
  [ -z "$p" ] && continue
  printf '%s\n' "$out" | grep -Eq -- "$p" || { echo "missing in the output: $p"; exit 1; }
done < "$patterns"
exit 0
