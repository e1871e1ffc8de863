# compare_runs.cmake - run two programs, each writing its results to a file
# given as its only argument, and fail unless both succeed with identical
# files (tests pitch_fixed_*: a fixed-configuration build against the full
# library; track_kernels_equal: tracking with this build's kernel set against
# the portable one). Usage: cmake -DA=prog -DB=prog -DOUT=prefix
# [-DEMU=emulator] -P compare_runs.cmake (EMU: the cross build's emulator,
# e.g. qemu-i386 for the 32-bit host build)
foreach(_side A B)
  execute_process(COMMAND ${EMU} ${${_side}} ${OUT}.${_side}.txt RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${${_side}} failed (${_rc})")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}.A.txt ${OUT}.B.txt
                RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${A} and ${B} differ: ${OUT}.A.txt, ${OUT}.B.txt")
endif()
file(STRINGS ${OUT}.A.txt _lines)
list(LENGTH _lines _n)
message(STATUS "identical: ${_n} lines")
