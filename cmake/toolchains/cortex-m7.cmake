# Cortex-M7 (ARMv7E-M, DSP, double-precision FPU, hard-float ABI): the
# armv7em kernels. Tests run on QEMU's mps2-an500.
set(SSDA_TARGET_NAME cortex-m7)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16")
set(SSDA_QEMU_MACHINE mps2-an500)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
