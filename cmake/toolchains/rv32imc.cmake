# RV32IMC (ILP32, soft float) with riscv64-unknown-elf-gcc, freestanding:
# Debian ships this compiler without a C library, so only the library is
# built (-ffreestanding; nothing is linked against a libc). Portable kernels.
# freestanding/string.h declares memcpy and memset only: the library may use
# nothing else from the C library, and this build proves it.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(SSDA_TARGET_NAME rv32imc)
set(SSDA_TARGET_CPU_FLAGS "-march=rv32imc -mabi=ilp32 -mcmodel=medlow")

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_AR riscv64-unknown-elf-ar CACHE FILEPATH "archiver")
set(CMAKE_RANLIB riscv64-unknown-elf-ranlib CACHE FILEPATH "ranlib")
set(CMAKE_SIZE riscv64-unknown-elf-size CACHE FILEPATH "size")
set(CMAKE_OBJDUMP riscv64-unknown-elf-objdump CACHE FILEPATH "objdump")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS} -ffreestanding -isystem ${CMAKE_CURRENT_LIST_DIR}/freestanding -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${SSDA_TARGET_CPU_FLAGS} -nostdlib -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(CMAKE_PROJECT_ssda_INCLUDE ${CMAKE_CURRENT_LIST_DIR}/../SsdaTarget.cmake)
