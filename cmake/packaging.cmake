# SPDX-License-Identifier: MIT
# What a distribution needs beside the programs: the AppStream metainfo that software
# centres read, and the Debian package `cpack -G DEB` makes from everything
# `cmake --install` installs (programs, .desktop entry, icon, metainfo and whatever other
# install rules the tree declares).
include(GNUInstallDirs)

set(AMAZEBALLS_APPSTREAM_ID "io.github.amazeballs.amazeballs")
set(AMAZEBALLS_HOMEPAGE "https://github.com/amazeballs/amazeballs"
    CACHE STRING "The project's home page, named in the AppStream metainfo and the Debian package")
set(AMAZEBALLS_SCREENSHOT_URL "https://raw.githubusercontent.com/amazeballs/amazeballs/main/docs/screenshots"
    CACHE STRING "Where software centres fetch docs/screenshots/*.png from (an https URL)")
set(AMAZEBALLS_PACKAGE_MAINTAINER "The Amazeballs developers <amazeballs@users.noreply.github.com>"
    CACHE STRING "The Debian package's Maintainer field: Name <address>")

# The release date of project(VERSION): SOURCE_DATE_EPOCH where a reproducible build sets
# it, else the date of the commit the sources are at, else today.
set(AMAZEBALLS_RELEASE_DATE "")
if(NOT DEFINED ENV{SOURCE_DATE_EPOCH})
  find_package(Git QUIET)
  if(GIT_FOUND)
    execute_process(COMMAND "${GIT_EXECUTABLE}" log -1 --format=%cs
                    WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}" RESULT_VARIABLE git_rc
                    OUTPUT_VARIABLE AMAZEBALLS_RELEASE_DATE OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT git_rc EQUAL 0 OR NOT AMAZEBALLS_RELEASE_DATE MATCHES "^[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]$")
      set(AMAZEBALLS_RELEASE_DATE "")
    endif()
  endif()
endif()
if(AMAZEBALLS_RELEASE_DATE STREQUAL "")
  string(TIMESTAMP AMAZEBALLS_RELEASE_DATE "%Y-%m-%d" UTC)
endif()

set(AMAZEBALLS_METAINFO "${CMAKE_BINARY_DIR}/${AMAZEBALLS_APPSTREAM_ID}.metainfo.xml")
configure_file("${CMAKE_SOURCE_DIR}/resources/amazeballs.metainfo.xml.in" "${AMAZEBALLS_METAINFO}" @ONLY)
if(AMAZEBALLS_BUILD_UI)
  install(FILES "${AMAZEBALLS_METAINFO}" DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
endif()

# The licence, where Debian policy puts it (machine-readable, DEP-5).
install(FILES "${CMAKE_SOURCE_DIR}/resources/copyright" DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/amazeballs)

# The Debian package: Depends comes from dpkg-shlibdeps (dpkg-dev) on the installed programs.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME amazeballs)
set(CPACK_PACKAGE_VENDOR "The Amazeballs developers")
set(CPACK_PACKAGE_CONTACT "${AMAZEBALLS_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_HOMEPAGE_URL "${AMAZEBALLS_HOMEPAGE}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "bouncing and colliding balls, stage by stage, for teaching physics")
set(CPACK_PACKAGE_DESCRIPTION
    "Amazeballs rebuilds the 2014 student report Amazeballs (Linköping University,
course TNM085) stage by stage: one ball bouncing in one dimension, one ball in
a box, two balls colliding, and a few hundred balls in a box. It runs the
report's own rules exactly and puts textbook physics beside them, with charts,
accuracy and stability studies and a lecture mode for a projector.

This package contains the window, amazeballs, and the command-line program,
amazeballs-cli, for scripted runs and lab reports.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${AMAZEBALLS_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt 6.4 on a Wayland session needs its Wayland plugin (else it falls back to XWayland);
# Qt's own words in the Swedish window (key names in the menus: "Mellanslag", "Höger"; the
# file dialogs' buttons) come from Qt's translations.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-wayland, qt6-translations-l10n")
set(CPACK_SOURCE_GENERATOR TXZ)
set(CPACK_SOURCE_IGNORE_FILES "/\\\\.git/" "/build[^/]*/")
include(CPack)
