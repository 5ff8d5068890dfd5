#!/usr/bin/env bash
# After strings were added or changed in the sources: brings i18n/ru/workbench.po up to the
# extracted POT (new msgids appear untranslated, with their c-format flags and source lines;
# gone ones become obsolete #~ entries). No fuzzy matching: a changed English string must be
# translated again, not guessed. Then translate the empty msgstrs and rebuild.
#   scripts/i18n/update_po.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
extra=()
[ -f "$build/labs/launcher/lab_list.h" ] && extra+=("$build/labs/launcher/lab_list.h")
"$root/scripts/i18n/extract.sh" "$root" "$build/i18n/workbench.pot" "${extra[@]}"
msgmerge --quiet --no-fuzzy-matching --no-wrap --update --backup=off \
  "$root/i18n/ru/workbench.po" "$build/i18n/workbench.pot"
# A msgid another fragment (i18n/ru/<branch>.po) translates is left to it: dropped here while
# untranslated, so the merged catalogue takes that fragment's translation.
others=$(ls "$root"/i18n/ru/*.po | grep -v '/workbench.po$' || true)
if [ -n "$others" ]; then
  tmp=$(mktemp -d)
  msgcat --use-first $others | msgattrib --translated -o "$tmp/others.po"
  msgattrib --untranslated -o "$tmp/untranslated.po" "$root/i18n/ru/workbench.po"
  if [ -s "$tmp/untranslated.po" ] && [ -s "$tmp/others.po" ]; then
    msgcomm --more-than=1 -o "$tmp/both.po" "$tmp/others.po" "$tmp/untranslated.po" || true
    if [ -s "$tmp/both.po" ]; then
      msgattrib --no-wrap --set-obsolete --only-file="$tmp/both.po" -o "$tmp/ru.po" "$root/i18n/ru/workbench.po"
      msgattrib --no-wrap --no-obsolete -o "$root/i18n/ru/workbench.po" "$tmp/ru.po"
    fi
  fi
  rm -rf "$tmp"
fi
msgfmt --check --statistics -o /dev/null "$root/i18n/ru/workbench.po"
