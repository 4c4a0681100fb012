# A Debian package of the application: `cpack` in the build folder (see the README). Included
# from the top CMakeLists.txt after the targets exist; app/ installs the executable to bin/.
#
# The layout is what core/resources.cpp looks for at run time: <prefix>/bin/lucerna and the
# bundled scenes, shaders, weather file and the README in <prefix>/share/lucerna.

include(GNUInstallDirs)

install(DIRECTORY ${CMAKE_SOURCE_DIR}/resources/scenes ${CMAKE_SOURCE_DIR}/resources/shaders
                  ${CMAKE_SOURCE_DIR}/resources/weather
        DESTINATION ${CMAKE_INSTALL_DATADIR}/lucerna)
# Help > User Guide shows it (ui/window/help_actions.h).
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/lucerna)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/lucerna.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/lucerna.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "lucerna")
set(CPACK_PACKAGE_VENDOR "Lucerna")
set(CPACK_PACKAGE_CONTACT "Lucerna developers <lucerna@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Lighting design with a live preview beside a converging physically based render")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # lucerna_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.invalid/lucerna")
# The runtime libraries (Qt 6, Embree, oneTBB, OpenEXR, Assimp, EGL) from the executable's
# ELF dependencies, so that `apt install ./lucerna_*.deb` pulls exactly what it links.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt loads its platform plugin (xcb) at run time, which shlibdeps cannot see; the software
# OpenGL driver lets the preview run without a GPU driver.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libgl1-mesa-dri")

include(CPack)
