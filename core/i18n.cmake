# The translations (issue 17): every i18n/<lang>/*.po (the main catalogue workbench.po first,
# then the fragments other branches add, e.g. i18n/ru/<branch>.po) merged by msgcat, checked
# and compiled by msgfmt --check (Debian's gettext), embedded into core (cmake/embed_mo.cmake).
# docs/i18n.md: why .mo files read by our own code and not glibc's gettext().
find_program(WB_MSGFMT msgfmt REQUIRED)
find_program(WB_MSGCAT msgcat REQUIRED)
set(WB_I18N_DIR ${PROJECT_SOURCE_DIR}/i18n)
set(WB_I18N_OUT ${CMAKE_BINARY_DIR}/i18n)
set(WB_I18N_LANGS ru)
set(catalogs "")
set(moFiles "")
foreach(lang IN LISTS WB_I18N_LANGS)
  file(GLOB fragments CONFIGURE_DEPENDS ${WB_I18N_DIR}/${lang}/*.po)
  list(REMOVE_ITEM fragments ${WB_I18N_DIR}/${lang}/workbench.po)
  list(SORT fragments)
  set(sources ${WB_I18N_DIR}/${lang}/workbench.po ${fragments})
  set(merged ${WB_I18N_OUT}/${lang}.po)
  set(mo ${WB_I18N_OUT}/${lang}.mo)
  # --use-first: where two files translate the same msgid, the main catalogue wins.
  add_custom_command(OUTPUT ${merged} ${mo}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${WB_I18N_OUT}
    COMMAND ${WB_MSGCAT} --use-first --to-code=UTF-8 -o ${merged} ${sources}
    COMMAND ${WB_MSGFMT} --check -o ${mo} ${merged}
    DEPENDS ${sources}
    COMMENT "Catalogue ${lang}: msgcat + msgfmt --check"
    VERBATIM)
  list(APPEND catalogs "${lang}=${mo}")
  list(APPEND moFiles ${mo})
endforeach()
add_custom_command(OUTPUT ${WB_I18N_OUT}/catalogs.cpp
  COMMAND ${CMAKE_COMMAND} "-DCATALOGS=${catalogs}" -DOUT=${WB_I18N_OUT}/catalogs.cpp
          -P ${PROJECT_SOURCE_DIR}/cmake/embed_mo.cmake
  DEPENDS ${moFiles} ${PROJECT_SOURCE_DIR}/cmake/embed_mo.cmake
  COMMENT "Embedding the catalogues"
  VERBATIM)
target_sources(core PRIVATE ${WB_I18N_OUT}/catalogs.cpp)
