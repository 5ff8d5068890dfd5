# Lab 08: the GL hemicube against core's CPU hemicube (occlusion), goldens flat and smooth,
# colour bleeding and smoothness properties of the picture, picking; the lab as a student and
# a careless user meet it (radiosity_lab_ui_test.cpp).
wb_test(radiosity_lab_test SOURCES radiosity_gl_hemicube_test.cpp radiosity_lab_render_test.cpp
  radiosity_lab_ui_test.cpp radiosity_preview_test.cpp LIBS lab08-radiosity_headless)
# Issue 20 item 10: a meshing the lab refuses exits non-zero and writes no PNG (was: exit 0 and
# a one-colour picture). Exit 1 exactly: a crash (signal) must not pass for a refusal.
set(lab08Refused ${CMAKE_CURRENT_BINARY_DIR}/lab08-refused.png)
add_test(NAME "cli: lab08 --scene classroom --patch-size 0.001 exits 1 without a PNG"
  COMMAND sh -c "rm -f \"$1\"; \"$0\" --scene classroom --patch-size 0.001 --size 64x48 --out \"$1\"; rc=$?; test $rc -eq 1 && test ! -e \"$1\""
          $<TARGET_FILE:lab08-radiosity-headless> ${lab08Refused})
# Issue 19 item 10: the crack census (background pixels enclosed by patches, every scene at
# the lab's default size and window), and that it fails on a cracked mesh.
wb_test(radiosity_crack_test SOURCES radiosity_crack_census_test.cpp LIBS lab08-radiosity_headless)
