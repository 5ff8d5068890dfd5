#!/usr/bin/env bash
# readme_keys.sh README.md README.ru.md: both list the same keys for every lab (issue 17).
# Per "### Lab NN" (ru: "### Лабораторная NN") section, the keys are the `backticked` words of
# the paragraph that starts with "Keys:" (ru: "Клавиши:"), in order.
set -uo pipefail
keys() {
  awk '
    /^### (Lab|Лабораторная) [0-9][0-9]/ { match($0, /[0-9][0-9]/); lab = substr($0, RSTART, 2); inkeys = 0; next }
    /^### / { lab = ""; inkeys = 0; next }
    lab != "" && /^(Keys|Клавиши):/ { inkeys = 1 }
    inkeys && /^$/ { inkeys = 0 }
    inkeys {
      line = $0
      while (match(line, /`[^`]+`/)) { printf "%s %s\n", lab, substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH) }
    }' "$1"
}
en=$(keys "$1") ru=$(keys "$2")
[ -n "$en" ] || { echo "no keys found in $1"; exit 1; }
if [ "$en" != "$ru" ]; then
  echo "the keys differ (< $1, > $2):"
  diff <(echo "$en") <(echo "$ru")
  exit 1
fi
echo "same keys: $(echo "$en" | wc -l) keys in $(echo "$en" | cut -d' ' -f1 | sort -u | wc -l) labs"
