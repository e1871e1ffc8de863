# Common part of the Cortex-M toolchain files: arm-none-eabi-gcc with newlib.
# Do not use directly; pick a core file (cortex-m0plus.cmake, cortex-m3.cmake,
# cortex-m4f.cmake, cortex-m7.cmake, cortex-m33.cmake), each of which sets
#   SSDA_TARGET_CPU_FLAGS  -mcpu/-mfpu/-mfloat-abi for compiler and linker
#   SSDA_QEMU_MACHINE      qemu-system-arm board that runs the tests (optional)
#   SSDA_TARGET_NAME       short name used in build directories and reports
# A cross build makes the library; with a QEMU board it also makes the Unity
# tests as bare-metal images that CTest runs under qemu-system-arm
# (cmake/SsdaTarget.cmake, tests/target/).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "archiver")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "ranlib")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "size")
set(CMAKE_OBJDUMP arm-none-eabi-objdump CACHE FILEPATH "objdump")

# No host linking in compiler checks: a bare-metal executable needs our
# startup code and linker script, which only exist for the test images.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Separate sections per function and object, so that --gc-sections keeps
# only what a firmware calls (what the size budget measures).
set(CMAKE_C_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS} -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# After project(ssda): the test-image hook and the QEMU emulator.
set(CMAKE_PROJECT_ssda_INCLUDE ${CMAKE_CURRENT_LIST_DIR}/../SsdaTarget.cmake)
