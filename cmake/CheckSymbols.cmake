# cmake -DNM=<nm> -DLIB=<libssda.a> -DINCLUDE=<include dir> [-DREPORT=<file>]
#       -P CheckSymbols.cmake
# The sealed library (lib/compiler.h): fails if the built library defines a
# global symbol that is neither a function or object declared in
# include/ssda/*.h nor prefixed `ssda__` (an internal shared by several lib
# files). Any other name would be exported into the user's firmware, where
# it could collide with the user's own (e.g. `stream_rect`), or would look
# public without being so. Run on the host (CTest: lib_symbols) and on the
# cross targets (the QEMU builds' CTest, and tools/test.sh on the M0+).
cmake_minimum_required(VERSION 3.16)
foreach(_v NM LIB INCLUDE)
  if(NOT DEFINED ${_v} OR "${${_v}}" STREQUAL "")
    message(FATAL_ERROR "CheckSymbols.cmake: -D${_v}=... is required")
  endif()
endforeach()

# Names the public headers declare: identifiers followed by '(' or ';' at
# the top level of a declaration, comments stripped. A superset is fine
# (macros, types): only names defined by the library are looked up.
file(GLOB _headers "${INCLUDE}/ssda/*.h")
set(_public "")
foreach(_h IN LISTS _headers)
  file(READ "${_h}" _text)
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" _text "${_text}")
  string(REGEX REPLACE "//[^\n]*" "" _text "${_text}")
  string(REGEX MATCHALL "ssda_[A-Za-z0-9_]*[ \t\n]*[(;]" _decls "${_text}")
  foreach(_d IN LISTS _decls)
    string(REGEX REPLACE "[ \t\n]*[(;]$" "" _d "${_d}")
    list(APPEND _public "${_d}")
  endforeach()
endforeach()
list(REMOVE_DUPLICATES _public)

execute_process(COMMAND "${NM}" -g --defined-only "${LIB}"
                OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "CheckSymbols.cmake: ${NM} failed on ${LIB}: ${_err}")
endif()
string(REPLACE "\n" ";" _lines "${_out}")
set(_bad "")
set(_exported "")
set(_internal 0)
foreach(_l IN LISTS _lines)
  # "<address> <type> <name>"; object headers ("x.c.o:") and blank lines skipped
  if(NOT _l MATCHES "^[0-9A-Fa-f]* *[A-Za-z] +([^ ]+)$")
    continue()
  endif()
  set(_name "${CMAKE_MATCH_1}")
  string(REGEX REPLACE "^_(ssda_)" "\\1" _name "${_name}") # Mach-O's leading underscore
  # instrumentation's companions of a variable (ASan's ODR indicator,
  # gcov's counters) are judged by the variable's name
  string(REGEX REPLACE "^(__odr_asan[._]|__gcov[0-9]*[._])" "" _name "${_name}")
  # the compiler's own helpers, emitted as hidden COMDAT copies in every
  # object that needs them (i386 PIC: __x86.get_pc_thunk.<reg>): not ours,
  # and the linker merges them
  if(_name MATCHES "^__x86\\.get_pc_thunk\\.")
    continue()
  endif()
  if(_name MATCHES "^ssda__")
    math(EXPR _internal "${_internal} + 1")
  elseif(_name IN_LIST _public)
    list(APPEND _exported "${_name}")
  else()
    list(APPEND _bad "${_name}")
  endif()
endforeach()
list(REMOVE_DUPLICATES _exported)
list(LENGTH _exported _n_public)
set(_summary "${LIB}: ${_n_public} public symbols, ${_internal} ssda__ internals")
if(DEFINED REPORT)
  string(REPLACE ";" "\n" _list "${_exported}")
  file(WRITE "${REPORT}" "${_summary}\n${_list}\n")
endif()
if(_bad)
  list(REMOVE_DUPLICATES _bad)
  string(REPLACE ";" "\n  " _msg "${_bad}")
  message(FATAL_ERROR
    "${LIB} exports names that are neither declared in include/ssda/*.h nor "
    "prefixed ssda__ (make them static, or rename them ssda__<module>_<name> "
    "and declare them SSDA_INTERNAL in a lib/ header; lib/compiler.h):\n  ${_msg}")
endif()
message(STATUS "${_summary}")
