# compare_runs.cmake - run two programs, each writing its results to a file
# given as its only argument, and fail unless both succeed with identical
# files (test pitch_fixed_*: a fixed-configuration build against the full
# library). Usage: cmake -DA=prog -DB=prog -DOUT=prefix -P compare_runs.cmake
foreach(_side A B)
  execute_process(COMMAND ${${_side}} ${OUT}.${_side}.txt RESULT_VARIABLE _rc)
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
