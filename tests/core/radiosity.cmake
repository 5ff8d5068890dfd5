# Radiosity core tests (issue 10): closed forms, the 2D example, hemicube, ray form factors,
# properties of F on every scene, solvers against a dense Eigen solve, furnace, bad input.
# Eigen (libeigen3-dev) is used by the tests only, as the independent direct solve.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
wb_test(radiosity_test
  SOURCES
    radiosity/closed_forms_test.cpp
    radiosity/flatland_test.cpp
    radiosity/mesh_test.cpp
    radiosity/hemicube_test.cpp
    radiosity/form_factors_test.cpp
    radiosity/solver_test.cpp
    radiosity/bad_input_test.cpp
    radiosity/group_rays_test.cpp
  LIBS core Eigen3::Eigen)
if(WORKBENCH_SANITIZE)
  target_compile_definitions(radiosity_test PRIVATE WB_SANITIZED=1)
endif()
