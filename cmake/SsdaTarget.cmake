# Cross builds: included at the end of project(ssda) by the toolchain files in
# cmake/toolchains/ (CMAKE_PROJECT_ssda_INCLUDE), never on a host build.
#
# With a QEMU board (SSDA_QEMU_MACHINE, set by the Cortex-M3/M4F/M7/M33 files):
#  - every Unity test becomes a bare-metal image: our startup code and vector
#    table, the board's linker script, newlib with semihosting (rdimon) for
#    output, and the exit status handed back to QEMU (tests/target/);
#  - CMAKE_CROSSCOMPILING_EMULATOR makes CTest run each image with
#    qemu-system-arm -M <board> -semihosting ... -kernel <image>;
#  - tests are compiled with SSDA_TEST_SMALL=1, the size knob heavy tests
#    read to keep emulated run times short (the same cases, smaller loops).
# Without a board (Cortex-M0+, RV32IMC) only the library is
# built unless SSDA_BUILD_TESTS is set explicitly.

# A firmware that adds ssda as a subproject under one of our toolchain files
# gets the library only: no test runtime in its ALL target, no emulator.
if(NOT CMAKE_SOURCE_DIR STREQUAL PROJECT_SOURCE_DIR AND NOT SSDA_BUILD_TESTS)
  return()
endif()

set(SSDA_TARGET_DIR ${CMAKE_CURRENT_LIST_DIR}/../tests/target)
get_filename_component(SSDA_TARGET_DIR ${SSDA_TARGET_DIR} ABSOLUTE)

if(NOT SSDA_QEMU_MACHINE)
  set(SSDA_BUILD_TESTS OFF CACHE BOOL "Build the Unity tests (no QEMU board for this target)")
  return()
endif()

set(SSDA_TARGET_LDSCRIPT ${SSDA_TARGET_DIR}/${SSDA_QEMU_MACHINE}.ld)
if(NOT EXISTS ${SSDA_TARGET_LDSCRIPT})
  message(FATAL_ERROR "ssda: no linker script for board ${SSDA_QEMU_MACHINE} in ${SSDA_TARGET_DIR}")
endif()

find_program(SSDA_QEMU_SYSTEM_ARM qemu-system-arm)
if(SSDA_QEMU_SYSTEM_ARM)
  set(CMAKE_CROSSCOMPILING_EMULATOR
      ${SSDA_QEMU_SYSTEM_ARM} -M ${SSDA_QEMU_MACHINE} -nographic -monitor none
      -serial none -semihosting-config enable=on,target=native -kernel)
  message(STATUS "ssda: tests run on qemu-system-arm -M ${SSDA_QEMU_MACHINE}")
else()
  message(WARNING "ssda: qemu-system-arm not found; test images are built but "
                  "CTest cannot run them (Debian: apt-get install qemu-system-arm)")
endif()

# The startup, semihosting and syscall glue shared by every test image.
add_library(ssda_target_rt OBJECT
    ${SSDA_TARGET_DIR}/startup.c
    ${SSDA_TARGET_DIR}/semihost.c)
target_include_directories(ssda_target_rt PUBLIC ${SSDA_TARGET_DIR})
set_target_properties(ssda_target_rt PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
target_compile_options(ssda_target_rt PRIVATE -Wall -Wextra)

# ssda_target_link_test(<executable>): make a test a bootable image for the
# board. Called by tests/CMakeLists.txt for every test when defined.
function(ssda_target_link_test tgt)
  # Objects, not an archive: the vector table is referenced by nothing but
  # the linker script, and must not be left out.
  target_sources(${tgt} PRIVATE $<TARGET_OBJECTS:ssda_target_rt>)
  target_link_options(${tgt} PRIVATE
      -T${SSDA_TARGET_LDSCRIPT} -L${SSDA_TARGET_DIR}
      -nostartfiles --specs=nano.specs --specs=rdimon.specs
      -Wl,-Map=$<TARGET_FILE:${tgt}>.map)
  # SSDA_EXPECT_KERNEL: test_kernel checks that the kernel set chosen at
  # configure time (lib/CMakeLists.txt) is the one linked.
  target_compile_definitions(${tgt} PRIVATE SSDA_TEST_SMALL=1
                             SSDA_EXPECT_KERNEL="${SSDA_KERNEL_SELECTED}")
  set_target_properties(${tgt} PROPERTIES SUFFIX .elf LINK_DEPENDS ${SSDA_TARGET_LDSCRIPT})
  # Test helpers may size their data by the same knob.
  if(TARGET ssda_testutil)
    get_target_property(_defs ssda_testutil COMPILE_DEFINITIONS)
    if(NOT _defs OR NOT "SSDA_TEST_SMALL=1" IN_LIST _defs)
      target_compile_definitions(ssda_testutil PUBLIC SSDA_TEST_SMALL=1)
    endif()
  endif()
endfunction()
