# Cortex-M4F (ARMv7E-M, DSP, single-precision FPU, hard-float ABI): the
# armv7em kernels (USADA8, SSUB16/SEL). Tests run on QEMU's mps2-an386.
set(SSDA_TARGET_NAME cortex-m4f)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
set(SSDA_QEMU_MACHINE mps2-an386)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
