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
    --package-name=workbench --add-comments=TRANSLATORS: --sort-by-file -f - -o "$out.main"
# The NFF reader names what it expected by literals given to its token readers
# (tk.point("sphere centre", line)), translated where the message is made: extracted here.
xgettext --keyword= --keyword=number:1 --keyword=coordinate:1 --keyword=point:1 --keyword=vec3:1 \
  --keyword=colour:1 --keyword=integer:1 --from-code=UTF-8 --language=C++ \
  --package-name=workbench -o "$out.nff" core/src/raytrace/nff.cpp
# The OBJ reader's the same way: err.number(word, line, "vertex coordinate").
xgettext --keyword= --keyword=number:3 --from-code=UTF-8 --language=C++ \
  --package-name=workbench -o "$out.obj" core/src/raytrace/obj_file.cpp
sed -i "s/charset=CHARSET/charset=UTF-8/" "$out.main" "$out.nff" "$out.obj"
msgcat --use-first -o "$out" "$out.main" "$out.nff" "$out.obj"
rm -f "$out.main" "$out.nff" "$out.obj"
