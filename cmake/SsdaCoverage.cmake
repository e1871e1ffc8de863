# SSDA_COVERAGE: gcov instrumentation (gcc --coverage) of the library and the
# tests, for tools/coverage.sh (lcov line and branch figures of lib/).
# Use with CMAKE_BUILD_TYPE=Debug: at -O0 every source branch keeps its own
# arc, so the branch figure counts what the source says, not what the
# optimiser left.
option(SSDA_COVERAGE "Instrument the library and tests for gcov/lcov (gcc)" OFF)
if(SSDA_COVERAGE)
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "ssda: SSDA_COVERAGE needs gcc (gcov), not ${CMAKE_C_COMPILER_ID}")
  endif()
  if(CMAKE_CROSSCOMPILING)
    message(FATAL_ERROR "ssda: SSDA_COVERAGE is for host builds (the tests write .gcda files)")
  endif()
  if(NOT CMAKE_BUILD_TYPE STREQUAL "Debug")
    message(STATUS "ssda: SSDA_COVERAGE with build type '${CMAKE_BUILD_TYPE}': branch "
                   "figures follow the optimiser (tools/coverage.sh uses Debug)")
  endif()
  add_compile_options(--coverage)
  add_link_options(--coverage)
endif()
