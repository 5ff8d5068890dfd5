# Lab 07: goldens of both modes, GLSL raster vs phong tracer, ray inspector on seed 000,
# cancel during a trace, the raster mesh's triangle budget, the timing experiment.
wb_test(raytrace_lab_test SOURCES raytrace_lab_render_test.cpp raytrace_lab_inspector_test.cpp
  raytrace_lab_cancel_test.cpp raytrace_lab_mesh_test.cpp
  raytrace_lab_experiment_test.cpp raytrace_lab_read_once_test.cpp LIBS lab07-raytrace_headless)

# Command-line front ends of the tracer (rt_render, lab07-raytrace --headless): a failed
# write, a piped progress bar (issue 12). Each case runs through sh so one test checks
# both the message and a non-zero exit code ("exit code N" is appended to the output).
set(scene ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/nff/two_spheres.nff)
set(lab07 $<TARGET_FILE:lab07-raytrace>)
set(rt $<TARGET_FILE:rt_render>)
function(wb_cli_fails name regex)
  add_test(NAME "${name}" COMMAND sh -c "\"$@\" 2>&1; echo \"exit code $?\"" sh ${ARGN})
  set_tests_properties("${name}" PROPERTIES PASS_REGULAR_EXPRESSION "${regex}.*exit code [1-9]")
endfunction()
# A device is refused before anything is written (issue 20 point 1: one rule for outputs).
wb_cli_fails("rt_render: --out /dev/full fails" "/dev/full: is a device, not a regular file"
  ${rt} ${scene} --size 16x16 --out /dev/full)
wb_cli_fails("rt_render: --out /proc/self/status fails" "/proc/self/status: "
  ${rt} ${scene} --size 16x16 --out /proc/self/status)
# /proc takes no new files even from root (CI's user, for whom a chmod-555 directory
# would not be read-only).
wb_cli_fails("rt_render: --out into a read-only directory fails" "/proc/wb-x.png: cannot create"
  ${rt} ${scene} --size 16x16 --out /proc/wb-x.png)
wb_cli_fails("lab07 headless: --out /dev/full fails" "/dev/full: is a device, not a regular file"
  ${lab07} --headless --scene one-sphere --size 16x16 --out /dev/full)
wb_cli_fails("lab07 headless: --out into a read-only directory fails" "/proc/wb-x.png: cannot"
  ${lab07} --headless --scene one-sphere --size 16x16 --out /proc/wb-x.png)
# Piped (ctest reads through a pipe): the bar is one line at the end, no \r redraws.
foreach(front "rt_render;${rt};${scene}" "lab07 headless;${lab07};--headless;--keys;G;--scene;${scene}")
  list(GET front 0 label)
  list(SUBLIST front 1 -1 cmd)
  add_test(NAME "${label}: piped progress bar is one line" COMMAND ${cmd} --size 64x64
    --out ${CMAKE_BINARY_DIR}/test-out/piped-${label}.png)
  string(ASCII 13 cr)
  set_tests_properties("${label}: piped progress bar is one line" PROPERTIES
    PASS_REGULAR_EXPRESSION "\\[#+\\] 100%\n" FAIL_REGULAR_EXPRESSION "${cr}")
endforeach()
# The OBJ reader's warnings (a missing .mtl, a face of 2 vertices) are shown, counted.
file(WRITE ${CMAKE_BINARY_DIR}/test-out/warn.obj
  "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n")
set(warnObj ${CMAKE_BINARY_DIR}/test-out/warn.obj)
add_test(NAME "rt_render: OBJ warnings are shown" COMMAND ${rt} ${warnObj} --size 16x16
  --out ${CMAKE_BINARY_DIR}/test-out/warn-rt.png)
add_test(NAME "lab07 headless: OBJ warnings are shown" COMMAND ${lab07} --headless
  --scene ${warnObj} --size 16x16 --out ${CMAKE_BINARY_DIR}/test-out/warn-lab.png)
set_tests_properties("rt_render: OBJ warnings are shown" "lab07 headless: OBJ warnings are shown"
  PROPERTIES PASS_REGULAR_EXPRESSION
  "warn.obj: 2 warnings:\n.*missing.mtl: material file not found.*warn.obj:6: face with fewer")
# --inspect prints the panel's ray tree: seed 000 part 2's worked example at P(50, 0) with
# the numbers the seed prints (t = 89.443, SH 0.530, LN 0.707, the reflected (236,73,73),
# the pixel (168,233,86)).
add_test(NAME "lab07 headless: --inspect prints seed 000's ray tree" COMMAND sh -c
  "\"$@\"; echo \"exit code $?\"" sh ${lab07} --headless --scene seed000-part2 --size 640x480
  --inspect 370,240 --out ${CMAKE_BINARY_DIR}/test-out/inspect.png)
set_tests_properties("lab07 headless: --inspect prints seed 000's ray tree" PROPERTIES
  PASS_REGULAR_EXPRESSION "pixel \\(370, 240\\), screen \\(50, 0\\).*hits rectangle #1 at t = 89.443 P = \\(40.000, 0.000, 20.000\\).*SH 0.530 LN 0.707.*\\+ reflected #1 \\(236, 73, 73\\) x kr 0.50.*= \\(168, 233, 86\\).*pixel RGB \\(168, 233, 86\\).*\\(same\\).*exit code 0")
wb_cli_fails("lab07 headless: --inspect outside the image fails" "--inspect 370,240 is outside the 64x48"
  ${lab07} --headless --scene seed000-part2 --size 64x48 --inspect 370,240
  --out ${CMAKE_BINARY_DIR}/test-out/inspect-out.png)
# A bad WB_BVH_PATH (the SIMD path override) must not end the lab: it is said and ignored
# (it threw from the BVH's constructor through the lab before).
add_test(NAME "lab07 headless: a bad WB_BVH_PATH is said and ignored" COMMAND sh -c
  "WB_BVH_PATH=bogus \"$@\" 2>&1; echo \"exit code $?\"" sh
  ${lab07} --headless --scene balls:1 --size 32x24 --keys G --out ${CMAKE_BINARY_DIR}/test-out/bad-bvh-path.png)
set_tests_properties("lab07 headless: a bad WB_BVH_PATH is said and ignored" PROPERTIES
  PASS_REGULAR_EXPRESSION "WB_BVH_PATH='bogus' ignored: expected sse4, avx4, avx8 or avx512.*exit code 0")
# --threads takes digits only (the shell's parser): strtol read "+2" and " 2" as 2.
wb_cli_fails("lab07 headless: --threads +2 is refused" "--threads: expected an integer 0..1024, got '\\+2'"
  ${lab07} --headless --scene seed000-part2 --size 16x12 --threads +2
  --out ${CMAKE_BINARY_DIR}/test-out/threads-plus.png)
add_test(NAME "lab07 --help names every built-in scene" COMMAND ${lab07} --help)
set_tests_properties("lab07 --help names every built-in scene" PROPERTIES
  PASS_REGULAR_EXPRESSION "diffuse-spheres.*seed000-part1-lit")
