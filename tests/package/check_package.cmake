# cmake -DSRC=<source dir> -DBUILD=<build dir> -DWORK=<scratch dir>
#       -DCC=<C compiler> -DPKG_CONFIG=<pkg-config> -P check_package.cmake
# Installs the built library into a scratch prefix, extracts the README's
# example (between the "readme-example" markers), builds it against the
# installed package with find_package(ssda), and runs it; then builds it
# again without CMake, as `cc readme_example.c $(pkg-config --cflags --libs ssda)`
# with the installed ssda.pc, and runs that too.
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

# The same example through pkg-config and the shell, as a Makefile user would.
if(NOT PKG_CONFIG OR NOT CC)
  message(FATAL_ERROR "check_package.cmake needs -DPKG_CONFIG=... and -DCC=...")
endif()
file(GLOB _pc "${WORK}/prefix/*/ssda.pc" "${WORK}/prefix/*/*/ssda.pc" "${WORK}/prefix/*/*/*/ssda.pc")
if(NOT _pc)
  message(FATAL_ERROR "no ssda.pc installed under ${WORK}/prefix")
endif()
get_filename_component(_pcdir "${_pc}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${_pcdir}")
set(ENV{PKG_CONFIG} "${PKG_CONFIG}")
set(ENV{CC} "${CC}")
execute_process(COMMAND sh -c "\"$CC\" -std=c99 -Wall -Wextra -Werror readme_example.c \
$(\"$PKG_CONFIG\" --cflags --libs ssda) -o readme_example_pc"
                WORKING_DIRECTORY "${WORK}/consumer" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the README example with pkg-config failed")
endif()
execute_process(COMMAND "${WORK}/consumer/readme_example_pc" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the README example built with pkg-config failed (exit ${rc})")
endif()
execute_process(COMMAND "${PKG_CONFIG}" --modversion ssda OUTPUT_VARIABLE _v
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(rc OR NOT _v STREQUAL VERSION)
  message(FATAL_ERROR "pkg-config --modversion ssda says '${_v}', the library is ${VERSION}")
endif()

# A build with the tool and help2man installs the man page.
if(EXISTS "${BUILD}/tools/cli/man/ssda.1")
  file(GLOB _man "${WORK}/prefix/*/man/man1/ssda.1" "${WORK}/prefix/*/*/man/man1/ssda.1")
  if(NOT _man)
    message(FATAL_ERROR "ssda.1 was built but not installed under ${WORK}/prefix")
  endif()
endif()
