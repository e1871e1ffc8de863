# Configure the project as a user without Unity and without network would:
# it must succeed, with the Unity tests off and one line saying so (issue 22).
# Two ways to have no network: FetchContent's own switch, and a repository
# that cannot be reached. An installed Unity package is hidden.
#   cmake -DSRC=<source dir> -DWORK=<scratch dir> -P check_no_unity.cmake
foreach(way disconnected unreachable)
  set(dir ${WORK}/${way})
  file(REMOVE_RECURSE ${dir})
  if(way STREQUAL disconnected)
    set(arg -DFETCHCONTENT_FULLY_DISCONNECTED=ON)
  else()
    set(arg -DSSDA_UNITY_GIT_REPOSITORY=file://${WORK}/no-such-repository.git)
  endif()
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${SRC} -B ${dir} -DSSDA_BUILD_TOOLS=OFF
            -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF -DCMAKE_DISABLE_FIND_PACKAGE_unity=ON
            ${arg}
    RESULT_VARIABLE rv OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rv EQUAL 0)
    message(FATAL_ERROR "configure without Unity (${way}) failed:\n${out}\n${err}")
  endif()
  string(REGEX MATCHALL "Unity tests are off" said "${out}${err}")
  list(LENGTH said n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "configure without Unity (${way}): expected one line saying the "
                        "tests are off, got ${n}:\n${out}\n${err}")
  endif()
  if(EXISTS ${dir}/tests/CTestTestfile.cmake)
    file(READ ${dir}/tests/CTestTestfile.cmake tests)
    if(tests MATCHES "add_test\\(test_")
      message(FATAL_ERROR "configure without Unity (${way}) still registered Unity tests")
    endif()
  endif()
  message(STATUS "${way}: ok")
endforeach()
