# Find the Unity test framework (ThrowTheSwitch), in this order:
#   1. an installed package: find_package(unity) -> unity::framework
#   2. a local source tree: FETCHCONTENT_SOURCE_DIR_UNITY (tools/fetch-unity.sh
#      makes one offline from Debian's cjson source package, Unity 2.4.3)
#   3. FetchContent from the upstream repository at a pinned tag (online).
# Only Unity API present in 2.4.3 is used. The result is target ssda_unity.
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

include(FetchContent)
FetchContent_Declare(unity
  GIT_REPOSITORY https://github.com/ThrowTheSwitch/Unity.git
  GIT_TAG v2.6.0
  GIT_SHALLOW TRUE)
FetchContent_GetProperties(unity)
if(NOT unity_POPULATED)
  # Populate only: we build unity.c ourselves so every route gives one target.
  FetchContent_Populate(unity)
endif()
if(NOT EXISTS "${unity_SOURCE_DIR}/src/unity.c")
  message(FATAL_ERROR "ssda: no Unity sources in ${unity_SOURCE_DIR}; run tools/fetch-unity.sh")
endif()
message(STATUS "ssda: Unity from source ${unity_SOURCE_DIR}")
add_library(ssda_unity STATIC "${unity_SOURCE_DIR}/src/unity.c")
target_include_directories(ssda_unity PUBLIC "${unity_SOURCE_DIR}/src")
target_compile_definitions(ssda_unity PUBLIC UNITY_SUPPORT_64)
set_target_properties(ssda_unity PROPERTIES C_STANDARD 99)
