# The installable package for a classroom's machines (issue 19): `cpack -G DEB` in the build
# folder (or `cmake --build build --target package`) makes workbench_<version>_<arch>.deb.
# Installed: /usr/bin/workbench and every lab (with its -headless twin, which the window
# starts for --headless), /usr/share/workbench/{assets,shaders,docs,thumbs}; the programs find
# that folder beside their own (labs/common/paths.h), so no source tree is needed.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets ${PROJECT_SOURCE_DIR}/shaders
                  ${PROJECT_SOURCE_DIR}/docs
        DESTINATION ${CMAKE_INSTALL_DATADIR}/workbench)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/workbench)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME workbench)
set(CPACK_PACKAGE_VERSION 0.19.0)
set(CPACK_PACKAGE_CONTACT "graphics course workbench <workbench@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Graphics lab workbench: OpenGL/GLUT labs with an ImGui panel and a CPU ray tracer")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION education)
# The runtime libraries (freeglut, GLEW, OSMesa, TBB, stb, ...) as dpkg-shlibdeps finds them
# in the binaries; the panel's font is read from its file, so it is named here.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_STRIP_FILES ON)
include(CPack)
