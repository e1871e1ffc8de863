# Cortex-M33 (ARMv8-M Mainline with the DSP extension, single-precision FPU,
# hard-float ABI): the armv7em kernels (same DSP instructions). Library only.
set(SSDA_TARGET_NAME cortex-m33)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
