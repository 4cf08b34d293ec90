# ctest kernel_bits_identical: runs the native and the SystemC-typed kernel tests with
# --gtest_filter=*Digest* and fails unless both pass and print the same, non-empty set of
# "DIGEST <name> <hex>" lines (digest.hpp): the kernels give identical bits in both type layers.
#   cmake -DNATIVE=<cig_kernel_tests> -DSYSTEMC=<cig_kernel_tests_systemc> -P compare_digests.cmake
foreach(var NATIVE SYSTEMC)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_digests.cmake: -D${var}=<test binary> is required")
  endif()
endforeach()

function(digest_lines binary out_var)
  execute_process(COMMAND ${binary} --gtest_filter=*Digest* --gtest_color=no
                  OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${binary} --gtest_filter=*Digest* failed (${status}):\n${output}\n${errors}")
  endif()
  string(REGEX MATCHALL "(^|\n)DIGEST [^\n]+" matches "${output}")
  set(lines "")
  foreach(m IN LISTS matches)
    string(STRIP "${m}" m)
    list(APPEND lines "${m}")
  endforeach()
  list(SORT lines)
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()

digest_lines(${NATIVE} native)
digest_lines(${SYSTEMC} systemc)
list(LENGTH native count)
if(count EQUAL 0)
  message(FATAL_ERROR "no DIGEST line printed by ${NATIVE}: the comparison would be vacuous")
endif()
if(NOT native STREQUAL systemc)
  string(REPLACE ";" "\n  " a "${native}")
  string(REPLACE ";" "\n  " b "${systemc}")
  message(FATAL_ERROR "kernel digests differ between the type layers:\nnative:\n  ${a}\nsystemc:\n  ${b}")
endif()
string(REPLACE ";" "\n  " a "${native}")
message(STATUS "${count} kernel digests identical in both type layers:\n  ${a}")
