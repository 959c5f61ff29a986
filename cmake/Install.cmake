# Install layout, manual pages and the Debian package (included from CMakeLists.txt after the abalike target).
#
# Debian's layout for games: the program in PREFIX/games, its data in PREFIX/share/games/abalike, everything
# else where every package puts it. `cmake --install build --prefix P` installs a working game into P;
# `cpack -G DEB` (in the build folder) packs the same tree with prefix /usr into abalike_VERSION-1_ARCH.deb.
set(ABALIKE_INSTALL_BINDIR games CACHE STRING "Where the abalike executable goes, relative to the prefix")
set(ABALIKE_INSTALL_DATADIR share/games/abalike CACHE STRING "Where levels/ and assets/ go, relative to the prefix")
# The AppStream component id and desktop file name are reverse-DNS names; example.abalike stands for the project's
# domain (the level schema's $id uses abalike.example) until it has one.
set(ABALIKE_MAINTAINER "the Angry Birds Alike authors <abalike@users.noreply.invalid>"
    CACHE STRING "Maintainer of the Debian package (name <address>)")

# The executable finds its data relative to itself: installed, BINDIR/../DATADIR; in a build tree, the copy
# staged below beside it (the build folder, where abalike is built). Never the source tree, so an installed or
# copied build needs no checkout.
file(RELATIVE_PATH _data_from_bin "/prefix/${ABALIKE_INSTALL_BINDIR}" "/prefix/${ABALIKE_INSTALL_DATADIR}")
set(ABALIKE_STAGED_DATA_DIR "${CMAKE_BINARY_DIR}/${ABALIKE_INSTALL_DATADIR}")
target_compile_definitions(abalike PRIVATE ABALIKE_VERSION="${PROJECT_VERSION}")
target_compile_definitions(abalike_app PRIVATE ABALIKE_DATA_FROM_INSTALLED_EXE="${_data_from_bin}"
                                               ABALIKE_DATA_FROM_BUILD_EXE="${ABALIKE_INSTALL_DATADIR}")

# Debian's hardening for the shipped program (dpkg-buildflags' defaults plus bindnow); sanitizer builds keep
# their own checks, which fortified libc calls would get in the way of.
if(NOT ABALIKE_SANITIZE AND NOT ABALIKE_FUZZ)
    foreach(_target abalike abalike_app abalike_cli abalike_plot)
        target_compile_definitions(${_target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:_FORTIFY_SOURCE=2>)
        target_compile_options(${_target} PRIVATE -fstack-protector-strong)
    endforeach()
    target_link_options(abalike PRIVATE -Wl,-z,relro -Wl,-z,now)
endif()

# ---------------------------------------------------------------- game data, staged in the build tree
file(GLOB_RECURSE _data_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/levels/* ${CMAKE_SOURCE_DIR}/assets/*)
add_custom_command(
    OUTPUT ${CMAKE_BINARY_DIR}/staged-data.stamp
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${ABALIKE_STAGED_DATA_DIR}
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${CMAKE_SOURCE_DIR}/levels ${ABALIKE_STAGED_DATA_DIR}/levels
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${CMAKE_SOURCE_DIR}/assets ${ABALIKE_STAGED_DATA_DIR}/assets
    COMMAND ${CMAKE_COMMAND} -E touch ${CMAKE_BINARY_DIR}/staged-data.stamp
    DEPENDS ${_data_files}
    COMMENT "Staging levels/ and assets/ in ${ABALIKE_INSTALL_DATADIR}/")
add_custom_target(abalike_data ALL DEPENDS ${CMAKE_BINARY_DIR}/staged-data.stamp)
add_dependencies(abalike abalike_data)

# ---------------------------------------------------------------- manual pages, from --help at build time
find_program(ABALIKE_HELP2MAN help2man)
set(ABALIKE_MAN_DIR ${CMAKE_BINARY_DIR}/man)
if(ABALIKE_HELP2MAN)
    add_custom_command(
        OUTPUT ${ABALIKE_MAN_DIR}/abalike.6.gz
        COMMAND ${CMAKE_COMMAND} -DABALIKE=$<TARGET_FILE:abalike> -DOUT=${ABALIKE_MAN_DIR}
                -DVERSION=${PROJECT_VERSION} -DHELP2MAN=${ABALIKE_HELP2MAN}
                -DINCLUDE=${CMAKE_SOURCE_DIR}/packaging/abalike.h2m -P ${CMAKE_SOURCE_DIR}/cmake/ManPages.cmake
        DEPENDS abalike ${CMAKE_SOURCE_DIR}/packaging/abalike.h2m ${CMAKE_SOURCE_DIR}/cmake/ManPages.cmake
        COMMENT "Generating the manual pages from abalike --help")
    add_custom_target(abalike_man ALL DEPENDS ${ABALIKE_MAN_DIR}/abalike.6.gz)
else()
    message(WARNING "help2man not found (Debian: help2man): installing without manual pages")
endif()

# ---------------------------------------------------------------- changelog, compressed as Debian wants it
add_custom_command(
    OUTPUT ${CMAKE_BINARY_DIR}/packaging/changelog.Debian.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/packaging
    COMMAND gzip -9nc ${CMAKE_SOURCE_DIR}/packaging/changelog > ${CMAKE_BINARY_DIR}/packaging/changelog.Debian.gz
    DEPENDS ${CMAKE_SOURCE_DIR}/packaging/changelog
    VERBATIM)
add_custom_target(abalike_changelog ALL DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog.Debian.gz)

# The release history is written by hand; make sure its newest entries name this version.
file(STRINGS ${CMAKE_SOURCE_DIR}/packaging/changelog _changelog_top LIMIT_COUNT 1)
file(READ ${CMAKE_SOURCE_DIR}/packaging/example.abalike.Abalike.metainfo.xml _metainfo)
if(NOT _changelog_top MATCHES "^abalike \\(${PROJECT_VERSION}-[0-9]+\\)")
    message(FATAL_ERROR "packaging/changelog: the newest entry is not version ${PROJECT_VERSION}: ${_changelog_top}")
endif()
if(NOT _metainfo MATCHES "<release version=\"${PROJECT_VERSION}\"")
    message(FATAL_ERROR "packaging/example.abalike.Abalike.metainfo.xml has no <release version=\"${PROJECT_VERSION}\">")
endif()
string(REGEX REPLACE "^abalike \\([^-]+-([0-9]+)\\).*" "\\1" ABALIKE_DEBIAN_REVISION "${_changelog_top}")

# ---------------------------------------------------------------- what gets installed
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
                                                WORLD_READ WORLD_EXECUTE)
install(TARGETS abalike RUNTIME DESTINATION ${ABALIKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/levels ${CMAKE_SOURCE_DIR}/assets DESTINATION ${ABALIKE_INSTALL_DATADIR})
install(FILES packaging/example.abalike.Abalike.desktop DESTINATION share/applications)
install(FILES packaging/abalike.svg DESTINATION share/icons/hicolor/scalable/apps)
install(FILES packaging/example.abalike.Abalike.metainfo.xml DESTINATION share/metainfo)
install(FILES packaging/copyright ${CMAKE_BINARY_DIR}/packaging/changelog.Debian.gz DESTINATION share/doc/abalike)
install(FILES packaging/lintian-overrides DESTINATION share/lintian/overrides RENAME abalike)
if(ABALIKE_HELP2MAN)
    install(DIRECTORY ${ABALIKE_MAN_DIR}/ DESTINATION share/man/man6 FILES_MATCHING PATTERN "*.6.gz")
endif()

# ---------------------------------------------------------------- the Debian package
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME abalike)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${ABALIKE_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "slingshot physics game and physics teaching tool")
# The long description; CPack puts the summary above it and indents it as a control file wants.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Pull the slingshot and launch birds of different mass and size at pigs
sheltered by wood, ice and stone. While you aim, an RK4 trajectory preview
shows the flight; after the shot the predicted path is drawn next to the
flown one. The 25-level campaign teaches launch angle and range, mass, air
drag, wind, momentum, materials and gravity on other worlds. Levels are JSON
files; the command line checks, solves and simulates them headless.")
set(CPACK_DEBIAN_PACKAGE_RELEASE ${ABALIKE_DEBIAN_REVISION})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Linked libraries come from dpkg-shlibdeps; these are loaded at run time without being linked: the font (by
# path for the game, through fontconfig for the plots) and the Mesa GL drivers SFML's OpenGL context needs.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
