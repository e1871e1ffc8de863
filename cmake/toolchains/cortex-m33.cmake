# Cortex-M33 (ARMv8-M Mainline with the DSP extension, single-precision FPU,
# hard-float ABI): the armv7em kernels (same DSP instructions). Tests run on
# QEMU's mps2-an505 (Secure state).
set(SSDA_TARGET_NAME cortex-m33)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16")
set(SSDA_QEMU_MACHINE mps2-an505)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
