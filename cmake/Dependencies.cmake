# Every dependency comes from a Debian package (scripts/setup.sh installs them).
find_package(OpenGL REQUIRED COMPONENTS OpenGL)
find_package(GLUT REQUIRED)
find_package(GLEW REQUIRED)
find_package(glm REQUIRED)
find_package(Catch2 2 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)

find_library(GLU_LIBRARY GLU REQUIRED)
# libstb-dev ships stb as a shared library (libstb.so: stb_image, stb_image_write, stb_truetype).
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# The window path reads key presses from X itself (labs/common/x_keyboard.h, issue 17).
pkg_check_modules(X11 REQUIRED IMPORTED_TARGET x11)
pkg_check_modules(XKBCOMMON REQUIRED IMPORTED_TARGET xkbcommon)

# Dear ImGui: Debian ships libimgui.a and headers; the GLUT and OpenGL2 backends
# come as sources in the package's doc folder and are compiled here.
find_library(IMGUI_LIBRARY imgui REQUIRED)
find_path(IMGUI_INCLUDE_DIR imgui.h PATHS /usr/include/imgui REQUIRED)
set(IMGUI_BACKEND_DIR /usr/share/doc/libimgui-dev/examples/backends
    CACHE PATH "Folder with imgui_impl_glut.cpp and imgui_impl_opengl2.cpp")
add_library(imgui_glut STATIC
  ${IMGUI_BACKEND_DIR}/imgui_impl_glut.cpp
  ${IMGUI_BACKEND_DIR}/imgui_impl_opengl2.cpp)
target_include_directories(imgui_glut PUBLIC ${IMGUI_INCLUDE_DIR} ${IMGUI_INCLUDE_DIR}/backends)
target_link_libraries(imgui_glut PUBLIC ${IMGUI_LIBRARY} PkgConfig::STB GLUT::GLUT OpenGL::GL)
target_compile_options(imgui_glut PRIVATE -w)

# The ImGui core alone, for the headless path (no GLUT, no libGL).
add_library(imgui_core INTERFACE)
target_include_directories(imgui_core INTERFACE ${IMGUI_INCLUDE_DIR})
target_link_libraries(imgui_core INTERFACE ${IMGUI_LIBRARY} PkgConfig::STB)
