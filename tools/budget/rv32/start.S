/* start.S - RV32 reset entry for the size-budget images: set the stack and
   global pointers, then the C start (rv32/start.c). Never run. */
    .section .text.start, "ax"
    .globl _start
_start:
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    la sp, __stack_top__
    call ssda_rv32_start
1:  j 1b
