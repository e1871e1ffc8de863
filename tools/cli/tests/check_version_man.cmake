# cmake -DSSDA=<ssda> -DVERSION=<library version> [-DMAN=<ssda.1>] -P check_version_man.cmake
# `ssda --version` prints the library's version (VERSION: the build's
# project version, read from SSDA_VERSION_* in include/ssda/ssda.h), and the
# man page states that version and has a section for every command.
execute_process(COMMAND "${SSDA}" --version OUTPUT_VARIABLE out RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc OR NOT out STREQUAL "ssda ${VERSION}")
  message(FATAL_ERROR "ssda --version printed '${out}' (exit ${rc}); the library is ${VERSION}")
endif()
if(NOT MAN)
  return()
endif()
file(READ "${MAN}" page)
string(REPLACE "." "\\." v "${VERSION}")
if(NOT page MATCHES "\n\\.TH SSDA \"1\" \"[^\"]+\" \"ssda ${v}\"")
  message(FATAL_ERROR "${MAN}: no .TH line stating ssda ${VERSION}")
endif()
execute_process(COMMAND "${SSDA}" --help OUTPUT_VARIABLE help)
string(REGEX MATCHALL "\n  [a-z][a-z0-9-]* " cmds "${help}")
foreach(c IN LISTS cmds)
  string(STRIP "${c}" c)
  if(NOT page MATCHES "\n\\.SS \"ssda ${c}\"\n\\.nf\nusage: ssda ${c} ")
    message(FATAL_ERROR "${MAN}: no section with 'ssda ${c} --help'")
  endif()
endforeach()
# groff, where installed, reads it without a warning.
find_program(GROFF groff)
if(GROFF)
  execute_process(COMMAND "${GROFF}" -man -Tutf8 -ww -z "${MAN}" ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(rc OR NOT err STREQUAL "")
    message(FATAL_ERROR "groff warns about ${MAN}: ${err}")
  endif()
endif()
