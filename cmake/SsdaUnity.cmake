# Find the Unity test framework (ThrowTheSwitch), in this order:
#   1. an installed package: find_package(unity) -> unity::framework
#   2. a local source tree: FETCHCONTENT_SOURCE_DIR_UNITY (tools/fetch-unity.sh
#      makes one offline from Debian's cjson source package, Unity 2.4.3)
#   3. a shallow clone of the upstream repository at a pinned tag (online),
#      unless FETCHCONTENT_FULLY_DISCONNECTED is set.
# Only Unity API present in 2.4.3 is used. The result is target ssda_unity and
# SSDA_HAVE_UNITY ON. When none of these works (no package, no network), the
# Unity tests are left out and one line says so: the library and the tools
# (with their CLI tests) do not need Unity, and configuring must not fail for
# a user who only wants them.
set(SSDA_HAVE_UNITY ON)
if(TARGET ssda_unity)
  return()
endif()

if(NOT FETCHCONTENT_SOURCE_DIR_UNITY)
  find_package(unity CONFIG QUIET)
endif()

if(unity_FOUND AND TARGET unity::framework)
  message(STATUS "ssda: Unity from installed package")
  add_library(ssda_unity INTERFACE)
  target_link_libraries(ssda_unity INTERFACE unity::framework)
  return()
endif()

set(SSDA_UNITY_GIT_REPOSITORY "https://github.com/ThrowTheSwitch/Unity.git"
    CACHE STRING "Where configure clones Unity from when it is not installed")
mark_as_advanced(SSDA_UNITY_GIT_REPOSITORY)
set(_unity_src "${FETCHCONTENT_SOURCE_DIR_UNITY}")
if(NOT _unity_src)
  set(_unity_src "${CMAKE_BINARY_DIR}/_deps/unity-src")
  if(NOT EXISTS "${_unity_src}/src/unity.c" AND NOT FETCHCONTENT_FULLY_DISCONNECTED)
    # Not FetchContent: its failed download is a fatal configure error.
    find_package(Git QUIET)
    if(GIT_FOUND)
      file(REMOVE_RECURSE "${_unity_src}")
      execute_process(
        COMMAND ${CMAKE_COMMAND} -E env GIT_TERMINAL_PROMPT=0
                ${GIT_EXECUTABLE} clone --quiet --depth 1 --branch v2.6.0
                ${SSDA_UNITY_GIT_REPOSITORY} "${_unity_src}"
        RESULT_VARIABLE _unity_rv OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
      if(NOT _unity_rv EQUAL 0)
        file(REMOVE_RECURSE "${_unity_src}")
      endif()
    endif()
  endif()
endif()
if(NOT EXISTS "${_unity_src}/src/unity.c")
  message(STATUS "ssda: Unity not found and not fetched: Unity tests are off "
                 "(tools/fetch-unity.sh makes a copy offline, then "
                 "-DFETCHCONTENT_SOURCE_DIR_UNITY=DIR)")
  set(SSDA_HAVE_UNITY OFF)
  return()
endif()
message(STATUS "ssda: Unity from source ${_unity_src}")
add_library(ssda_unity STATIC "${_unity_src}/src/unity.c")
target_include_directories(ssda_unity PUBLIC "${_unity_src}/src")
target_compile_definitions(ssda_unity PUBLIC UNITY_SUPPORT_64)
set_target_properties(ssda_unity PROPERTIES C_STANDARD 99)
