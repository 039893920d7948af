# SPDX-License-Identifier: MIT
# Validates the .desktop entry and the AppStream metainfo the way distributions do, then
# checks what the validators cannot know: the release is project(VERSION), the launchable
# is the .desktop entry installed beside it, both programs are provided, and every
# screenshot is one of docs/screenshots/*.png with the width and height it states.
# Run as: cmake -DDESKTOP=... -DMETAINFO=... -DVERSION=... -DSCREENSHOTS=<dir>
#               -DDESKTOP_FILE_VALIDATE=... -DAPPSTREAMCLI=... -P check_desktop_metadata.cmake
cmake_minimum_required(VERSION 3.22)
execute_process(COMMAND "${DESKTOP_FILE_VALIDATE}" "${DESKTOP}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out STREQUAL "")
  message(FATAL_ERROR "desktop-file-validate ${DESKTOP} (exit ${rc}):\n${out}")
endif()

# --no-net: the screenshot and home page URLs are checked for form, not fetched. Errors,
# warnings and infos all fail; only pedantic notes are let through.
execute_process(COMMAND "${APPSTREAMCLI}" validate --no-net --strict --no-color "${METAINFO}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR out MATCHES "(^|\n)[EWI]: ")
  message(FATAL_ERROR "appstreamcli validate --no-net ${METAINFO} (exit ${rc}):\n${out}")
endif()

file(READ "${METAINFO}" xml)
get_filename_component(desktopName "${DESKTOP}" NAME)
get_filename_component(metainfoName "${METAINFO}" NAME)
string(REGEX MATCH "<id>([^<]+)</id>" _ "${xml}")
if(NOT metainfoName STREQUAL "${CMAKE_MATCH_1}.metainfo.xml")
  message(FATAL_ERROR "${metainfoName} is not named after its component id '${CMAKE_MATCH_1}'")
endif()
if(NOT xml MATCHES "<release version=\"${VERSION}\" date=\"[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]\"")
  message(FATAL_ERROR "the metainfo's release is not project(VERSION) ${VERSION} with a date")
endif()
if(NOT xml MATCHES "<launchable type=\"desktop-id\">${desktopName}</launchable>")
  message(FATAL_ERROR "the metainfo does not launch ${desktopName}")
endif()
foreach(binary amazeballs amazeballs-cli)
  if(NOT xml MATCHES "<binary>${binary}</binary>")
    message(FATAL_ERROR "the metainfo does not provide the binary ${binary}")
  endif()
endforeach()
if(NOT xml MATCHES "<content_rating type=\"oars-1\\.1\"")
  message(FATAL_ERROR "the metainfo has no OARS content rating")
endif()

# Every <image>: its file under docs/screenshots, and the PNG header's width and height
# (big-endian 32-bit integers at bytes 16 and 20) equal to those the metainfo states.
string(REGEX MATCHALL "<image type=\"source\" width=\"[0-9]+\" height=\"[0-9]+\">[^<]+</image>" images "${xml}")
list(LENGTH images count)
if(count LESS 1)
  message(FATAL_ERROR "the metainfo has no screenshot image with its width and height")
endif()
foreach(image IN LISTS images)
  string(REGEX MATCH "width=\"([0-9]+)\" height=\"([0-9]+)\">https://[^<]+/([^/<]+\\.png)<" _ "${image}")
  set(w "${CMAKE_MATCH_1}")
  set(h "${CMAKE_MATCH_2}")
  set(png "${SCREENSHOTS}/${CMAKE_MATCH_3}")
  if(CMAKE_MATCH_3 STREQUAL "" OR NOT EXISTS "${png}")
    message(FATAL_ERROR "screenshot ${image}: not an https URL of a file in ${SCREENSHOTS}")
  endif()
  file(READ "${png}" header LIMIT 24 HEX)
  string(SUBSTRING "${header}" 32 8 wHex)
  string(SUBSTRING "${header}" 40 8 hHex)
  math(EXPR pngW "0x${wHex}")
  math(EXPR pngH "0x${hHex}")
  if(NOT header MATCHES "^89504e470d0a1a0a" OR NOT pngW EQUAL w OR NOT pngH EQUAL h)
    message(FATAL_ERROR "${png} is ${pngW}x${pngH}, the metainfo says ${w}x${h}")
  endif()
endforeach()
message(STATUS "valid: ${desktopName} and ${metainfoName} (release ${VERSION}, ${count} screenshots)")
