# cmake -DSRC=<source dir> -DBUILD=<build dir> -DWORK=<scratch dir> -P check_package.cmake
# Installs the built library into a scratch prefix, extracts the README's
# example (between the "readme-example" markers), builds it against the
# installed package with find_package(ssda), and runs it.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed")
endif()
file(READ "${SRC}/README.md" readme)
string(REGEX MATCH "<!-- readme-example -->\n```c\n(.*)```\n<!-- /readme-example -->" _ "${readme}")
if(NOT CMAKE_MATCH_1)
  message(FATAL_ERROR "README.md has no example between the readme-example markers")
endif()
file(MAKE_DIRECTORY "${WORK}/consumer")
file(WRITE "${WORK}/consumer/readme_example.c" "${CMAKE_MATCH_1}")
file(COPY "${SRC}/tests/package/CMakeLists.txt" DESTINATION "${WORK}/consumer")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${WORK}/consumer" -B "${WORK}/consumer/build"
                        -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_C_FLAGS=-Werror\ -Wall\ -Wextra
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/consumer/build" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the README example failed")
endif()
execute_process(COMMAND "${WORK}/consumer/build/readme_example" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the README example failed (exit ${rc})")
endif()
