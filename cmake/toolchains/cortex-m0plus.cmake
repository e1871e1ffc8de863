# Cortex-M0+ (ARMv6-M): no DSP, no FPU, no hardware divide. Library only
# (QEMU has no Cortex-M0+ board): the size budget's reference core.
set(SSDA_TARGET_NAME cortex-m0plus)
set(SSDA_TARGET_CPU_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
