# Cortex-M3 (ARMv7-M): no DSP, no FPU; portable kernels.
# Tests run on QEMU's mps2-an385.
set(SSDA_TARGET_NAME cortex-m3)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(SSDA_QEMU_MACHINE mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
