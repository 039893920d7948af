# SPDX-License-Identifier: MIT
# Installs the build into a fresh prefix and checks what a Linux desktop needs: the
# programs in bin, the .desktop entry whose Exec and Icon name them, and the icon in the
# hicolor theme, and the AppStream metainfo that launches that entry and provides both
# programs, and the man pages and shell completions.
# Run as: cmake -DBUILD_DIR=... -DPREFIX=... [-DVALIDATE=...] -P check_install.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()

set(desktop "${PREFIX}/share/applications/amazeballs.desktop")
set(icon "${PREFIX}/share/icons/hicolor/scalable/apps/amazeballs.svg")
foreach(f "${PREFIX}/bin/amazeballs" "${PREFIX}/bin/amazeballs-cli" "${desktop}" "${icon}")
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

file(STRINGS "${desktop}" exec REGEX "^Exec=")
file(STRINGS "${desktop}" iconKey REGEX "^Icon=")
if(NOT exec MATCHES "^Exec=amazeballs( |$)")
  message(FATAL_ERROR "the .desktop entry runs '${exec}', not the installed amazeballs")
endif()
if(NOT iconKey STREQUAL "Icon=amazeballs")
  message(FATAL_ERROR "the .desktop entry names '${iconKey}', not the installed icon amazeballs.svg")
endif()
file(READ "${icon}" svg)
if(NOT svg MATCHES "<svg")
  message(FATAL_ERROR "the installed icon is not an SVG image")
endif()

# Software centres read share/metainfo/<component id>.metainfo.xml.
file(GLOB metainfo "${PREFIX}/share/metainfo/*.metainfo.xml")
list(LENGTH metainfo count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one AppStream metainfo in ${PREFIX}/share/metainfo, found ${count}")
endif()
file(READ "${metainfo}" xml)
if(NOT xml MATCHES "<launchable type=\"desktop-id\">amazeballs.desktop</launchable>"
   OR NOT xml MATCHES "<binary>amazeballs</binary>" OR NOT xml MATCHES "<binary>amazeballs-cli</binary>")
  message(FATAL_ERROR "${metainfo} does not launch amazeballs.desktop and provide both programs")
endif()

if(VALIDATE)
  execute_process(COMMAND "${VALIDATE}" "${desktop}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR out MATCHES "error")
    message(FATAL_ERROR "desktop-file-validate: ${out}")
  endif()
endif()
# The man pages where man finds them, the completions where bash-completion and zsh do.
foreach(program amazeballs amazeballs-cli)
  file(GLOB man "${PREFIX}/share/man/man1/${program}.1" "${PREFIX}/share/man/man1/${program}.1.gz")
  if(NOT man OR NOT EXISTS "${PREFIX}/share/bash-completion/completions/${program}"
     OR NOT EXISTS "${PREFIX}/share/zsh/vendor-completions/_${program}")
    message(FATAL_ERROR "${program}: man page or shell completion not installed under ${PREFIX}/share")
  endif()
endforeach()
message(STATUS "installed: programs, desktop entry, icon, metainfo, man pages and completions in ${PREFIX}")
