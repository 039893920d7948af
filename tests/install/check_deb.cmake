# SPDX-License-Identifier: MIT
# Makes the Debian package from the built tree with `cpack -G DEB` into a fresh folder and
# reads it back with dpkg-deb: its control fields, that it holds exactly the files
# `cmake --install` installs (so whatever install rule the tree gains is packaged too),
# among them the programs, desktop entry, icon, metainfo, copyright, man pages and bash and
# zsh completions, and that the packaged amazeballs-cli runs. cpack first brings the tree
# up to date (its preinstall step), which on a built tree is only make's check.
# Run as: cmake -DBUILD_DIR=... -DOUT=... -DVERSION=... -DMETAINFO_NAME=... -DMAN_SUFFIX=...
#               -DCPACK=... -DDPKG_DEB=... -DDPKG=... -DOBJDUMP=... -P check_deb.cmake
cmake_minimum_required(VERSION 3.22)
foreach(program amazeballs amazeballs-cli)
  if(NOT EXISTS "${BUILD_DIR}/app/${program}")
    message(FATAL_ERROR "${BUILD_DIR}/app/${program} is not built: build the tree before running the tests")
  endif()
endforeach()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

execute_process(COMMAND "${CPACK}" --config "${BUILD_DIR}/CPackConfig.cmake" -G DEB -B "${OUT}/cpack"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(GLOB debs "${OUT}/cpack/*.deb")
list(LENGTH debs count)
if(NOT rc EQUAL 0 OR NOT count EQUAL 1)
  message(FATAL_ERROR "cpack -G DEB (exit ${rc}) made ${count} packages:\n${out}")
endif()
set(deb "${debs}")

execute_process(COMMAND "${DPKG}" --print-architecture OUTPUT_VARIABLE arch OUTPUT_STRIP_TRAILING_WHITESPACE)
function(expect_field field pattern)
  execute_process(COMMAND "${DPKG_DEB}" --field "${deb}" "${field}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE value ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0 OR NOT value MATCHES "${pattern}")
    message(FATAL_ERROR "${deb}: ${field} is '${value}', expected to match '${pattern}' ${err}")
  endif()
  set(${field} "${value}" PARENT_SCOPE)
endfunction()
string(REPLACE "." "\\." versionRe "${VERSION}")
expect_field(Package "^amazeballs$")
expect_field(Version "^${versionRe}$")
expect_field(Architecture "^${arch}$")
expect_field(Maintainer "^[^<>]+ <[^<>@ ]+@[^<>@ ]+>$")
expect_field(Section "^science$")
expect_field(Description "^[a-z][^\n]+\n .+amazeballs-cli")
# dpkg-shlibdeps' Depends: the package of every library the two programs load (their
# ELF NEEDED entries, looked up with dpkg -S on this machine), among them Qt 6's.
expect_field(Depends "libqt6core6 \\(>= [0-9.]+\\)")
set(needed "")
foreach(program amazeballs amazeballs-cli)
  execute_process(COMMAND "${OBJDUMP}" -p "${BUILD_DIR}/app/${program}" OUTPUT_VARIABLE dump)
  string(REGEX MATCHALL "NEEDED +[^ \n]+" entries "${dump}")
  list(TRANSFORM entries REPLACE "NEEDED +" "")
  list(APPEND needed ${entries})
endforeach()
list(REMOVE_DUPLICATES needed)
# One dpkg -S for all of them; the owner is the package of this architecture (libc6:amd64,
# not libc6-i386, which also ships an ld-linux-x86-64.so.2).
list(TRANSFORM needed PREPEND "*/" OUTPUT_VARIABLE patterns)
execute_process(COMMAND "${DPKG}" -S ${patterns} OUTPUT_VARIABLE owned ERROR_QUIET)
set(owners "")
foreach(soname IN LISTS needed)
  string(REPLACE "+" "\\+" sonameRe "${soname}")
  string(REPLACE "." "\\." sonameRe "${sonameRe}")
  if(NOT owned MATCHES "(^|\n)([^:, \n]+):${arch}: [^\n]*/${sonameRe}(\n|$)")
    message(FATAL_ERROR "no installed ${arch} package holds ${soname}, which the programs load")
  endif()
  list(APPEND owners "${CMAKE_MATCH_2}")
endforeach()
list(REMOVE_DUPLICATES owners)
foreach(pkg IN LISTS owners ITEMS libqt6gui6 libqt6widgets6 libqt6charts6)
  string(REPLACE "+" "\\+" pkgRe "${pkg}")
  if(NOT Depends MATCHES "(^|, )${pkgRe}( \\([<>=]+ [^)]+\\))?(,|$)")
    message(FATAL_ERROR "Depends lacks ${pkg}: ${Depends}")
  endif()
endforeach()

# The package's regular files, as paths under /usr, against those `cmake --install` puts
# under a prefix.
execute_process(COMMAND "${DPKG_DEB}" --contents "${deb}" RESULT_VARIABLE rc OUTPUT_VARIABLE listing)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dpkg-deb --contents ${deb} failed (${rc})")
endif()
string(REGEX MATCHALL "(^|\n)-[^\n]+ \\./usr/[^\n]+" rows "${listing}")
set(packaged "")
foreach(row IN LISTS rows)
  string(REGEX MATCH "^\n?(-[rwx-]+) ([a-z]+/[a-z]+) .* \\./usr/(.+)$" _ "${row}")
  set(mode "${CMAKE_MATCH_1}")
  set(owner "${CMAKE_MATCH_2}")
  set(path "${CMAKE_MATCH_3}")
  if(NOT owner STREQUAL "root/root")
    message(FATAL_ERROR "not owned by root: ${row}")
  endif()
  if(path MATCHES "^bin/" AND NOT mode STREQUAL "-rwxr-xr-x")
    message(FATAL_ERROR "not an executable program: ${row}")
  endif()
  list(APPEND packaged "${path}")
endforeach()
foreach(f bin/amazeballs bin/amazeballs-cli share/applications/amazeballs.desktop
          share/icons/hicolor/scalable/apps/amazeballs.svg share/metainfo/${METAINFO_NAME}
          share/doc/amazeballs/copyright share/man/man1/amazeballs.1${MAN_SUFFIX}
          share/man/man1/amazeballs-cli.1${MAN_SUFFIX} share/bash-completion/completions/amazeballs
          share/bash-completion/completions/amazeballs-cli share/zsh/vendor-completions/_amazeballs
          share/zsh/vendor-completions/_amazeballs-cli)
  if(NOT f IN_LIST packaged)
    message(FATAL_ERROR "${deb} lacks /usr/${f}; it holds:\n${listing}")
  endif()
endforeach()

execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${OUT}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
file(GLOB_RECURSE installed RELATIVE "${OUT}/prefix" "${OUT}/prefix/*")
list(SORT installed)
list(SORT packaged)
if(NOT rc EQUAL 0 OR NOT installed STREQUAL packaged)
  message(FATAL_ERROR "the package holds\n  ${packaged}\nbut cmake --install installs\n  ${installed}")
endif()

# The packaged (stripped) command-line program runs and lists the report's scenes.
execute_process(COMMAND "${DPKG_DEB}" -x "${deb}" "${OUT}/root" RESULT_VARIABLE rc)
execute_process(COMMAND "${OUT}/root/usr/bin/amazeballs-cli" list RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "bounce1d" OR NOT out MATCHES "many-balls")
  message(FATAL_ERROR "the packaged amazeballs-cli list exited ${rc}: ${err}")
endif()
list(LENGTH packaged files)
message(STATUS "${deb}: ${Package} ${Version} ${Architecture}, ${files} files, Depends: ${Depends}")
