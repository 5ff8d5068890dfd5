add_lab(08-radiosity lab08-radiosity "Radiosity: patches, form factors by rays / CPU hemicube / GL hemicube, progressive refinement, smoothing, Cornell box"
  SOURCES radiosity_lab.cpp radiosity_run.cpp radiosity_display.cpp radiosity_panel.cpp radiosity_preview.cpp patch_view.cpp gl_hemicube.cpp hemicube_view.cpp exercise_view.cpp)
add_exercises(08 08-radiosity CHECKS exercise_checks.cpp)
