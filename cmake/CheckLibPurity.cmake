# cmake -DROOT=<source dir> -P CheckLibPurity.cmake
# Fails if lib/ or include/ use floating point, the heap or stdio: the
# library must stay freestanding and integer-only. Comments are ignored.
file(GLOB_RECURSE _files "${ROOT}/lib/*.c" "${ROOT}/lib/*.h" "${ROOT}/include/*.h")
set(_bad "")
foreach(f IN LISTS _files)
  file(READ "${f}" _text)
  # Strip /* ... */ and // comments before scanning.
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" _text "${_text}")
  string(REGEX REPLACE "//[^\n]*" "" _text "${_text}")
  foreach(word float double malloc calloc realloc free printf fprintf puts fopen stdio\\.h stdlib\\.h math\\.h)
    if(_text MATCHES "(^|[^A-Za-z0-9_])${word}([^A-Za-z0-9_]|$)")
      list(APPEND _bad "${f}: ${word}")
    endif()
  endforeach()
endforeach()
if(_bad)
  string(REPLACE ";" "\n  " _msg "${_bad}")
  message(FATAL_ERROR "lib/ or include/ uses forbidden float/heap/stdio:\n  ${_msg}")
endif()
