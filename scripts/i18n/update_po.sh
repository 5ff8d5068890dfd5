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
msgfmt --check --statistics -o /dev/null "$root/i18n/ru/workbench.po"
