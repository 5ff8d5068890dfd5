#!/usr/bin/env bash
# Extracts every translatable string of the sources into a POT file (issue 17):
#   extract.sh SOURCE_DIR OUT.pot [MORE_FILES...]
# Keywords: tr(), trf() and N_() (core/include/core/i18n.h). MORE_FILES: generated sources that
# hold strings (the launcher's lab list, built from the add_lab() descriptions).
set -euo pipefail
src=$1 out=$2
shift 2
cd "$src"
{ find labs core tests/bench -name '*.cpp' -o -name '*.h' | sort; printf '%s\n' "$@"; } |
  xgettext --keyword=tr --keyword=trf --keyword=N_ --from-code=UTF-8 --language=C++ \
    --package-name=workbench --add-comments=TRANSLATORS: --sort-by-file -f - -o "$out"
