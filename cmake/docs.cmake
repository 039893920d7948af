# SPDX-License-Identifier: MIT
# The man pages amazeballs(1) and amazeballs-cli(1) and both programs' bash and zsh
# completions, written at build time by amazeballs-docgen from the tables the parsers are
# made from, and installed where man-db, bash-completion and zsh look for them. The man
# pages are installed gzipped, as Debian ships them, where gzip is found.
include(GNUInstallDirs)
set(AMAZEBALLS_DOCS_DIR "${CMAKE_BINARY_DIR}/generated-docs")
set(docs man/amazeballs.1 man/amazeballs-cli.1 bash/amazeballs bash/amazeballs-cli zsh/_amazeballs zsh/_amazeballs-cli)
list(TRANSFORM docs PREPEND "${AMAZEBALLS_DOCS_DIR}/" OUTPUT_VARIABLE docOutputs)
find_program(GZIP gzip)
set(gzipCommands "")
set(AMAZEBALLS_MAN_SUFFIX "")
if(GZIP)
  set(AMAZEBALLS_MAN_SUFFIX ".gz")
  set(gzipCommands COMMAND "${GZIP}" -9nkf "${AMAZEBALLS_DOCS_DIR}/man/amazeballs.1"
                   COMMAND "${GZIP}" -9nkf "${AMAZEBALLS_DOCS_DIR}/man/amazeballs-cli.1")
  list(APPEND docOutputs "${AMAZEBALLS_DOCS_DIR}/man/amazeballs.1.gz" "${AMAZEBALLS_DOCS_DIR}/man/amazeballs-cli.1.gz")
endif()
add_custom_command(OUTPUT ${docOutputs}
                   COMMAND amazeballs-docgen "${AMAZEBALLS_DOCS_DIR}" "${PROJECT_VERSION}" "${AMAZEBALLS_RELEASE_DATE}"
                   ${gzipCommands}
                   DEPENDS amazeballs-docgen
                   COMMENT "Writing the man pages and shell completions"
                   VERBATIM)
add_custom_target(amazeballs_docs ALL DEPENDS ${docOutputs})

set(programs amazeballs-cli)
if(AMAZEBALLS_BUILD_UI)
  list(APPEND programs amazeballs)
endif()
foreach(program IN LISTS programs)
  install(FILES "${AMAZEBALLS_DOCS_DIR}/man/${program}.1${AMAZEBALLS_MAN_SUFFIX}" DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES "${AMAZEBALLS_DOCS_DIR}/bash/${program}" DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
  install(FILES "${AMAZEBALLS_DOCS_DIR}/zsh/_${program}" DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
endforeach()
