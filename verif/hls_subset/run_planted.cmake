# One planted violation (verif/hls_subset/planted/*.hpp) through the HLS-subset checker:
#   1. the checker fails (exit status 1: violations, not 2: the check could not run) and reports
#      every rule named by the file's "// expect: <rule>" lines, and no other rule;
#   2. the clean twin -- lines marked "// planted-only" removed, lines marked "// clean: <code>"
#      replaced by <code> -- passes, so the file fails for its planted reason alone.
#
#   cmake -DCHECKER=<hls_subset_check> -DCXX=<g++> -DROOT=<repository root> -DFILE=<planted header>
#         -DWORK=<scratch folder> -P run_planted.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var CHECKER CXX ROOT FILE WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_planted.cmake: -D${var}=... is required")
  endif()
endforeach()
get_filename_component(name "${FILE}" NAME)
file(REMOVE_RECURSE "${WORK}")

file(READ "${FILE}" source)
string(REGEX MATCHALL "// expect: [a-z-]+" expect_lines "${source}")
set(expected "")
foreach(e IN LISTS expect_lines)
  string(REGEX REPLACE "^// expect: " "" rule "${e}")
  list(APPEND expected "${rule}")
endforeach()
if(NOT expected)
  message(FATAL_ERROR "${name}: no '// expect: <rule>' line")
endif()

# ---- 1. the planted file fails, for the expected rules only --------------------------------------
execute_process(
  COMMAND "${CHECKER}" --cxx "${CXX}" --root "${ROOT}" --work "${WORK}/planted" "${FILE}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("---- checker on ${name} (expected to fail with: ${expected}) ----\n${out}${err}")
if(NOT rc STREQUAL "1")
  message(FATAL_ERROR "${name}: the checker exited with '${rc}', expected 1 (violations found)")
endif()
foreach(rule IN LISTS expected)
  if(NOT out MATCHES ":[0-9]+: ${rule}: ")
    message(FATAL_ERROR "${name}: the expected rule '${rule}' was not reported")
  endif()
endforeach()
string(REPLACE ";" "<semicolon>" out_escaped "${out}")
string(REPLACE "\n" ";" out_lines "${out_escaped}")
foreach(l IN LISTS out_lines)
  if(l MATCHES "^[^ ]+:[0-9]+: ([a-z-]+): ")
    if(NOT CMAKE_MATCH_1 IN_LIST expected)
      message(FATAL_ERROR "${name}: unexpected rule '${CMAKE_MATCH_1}' (the file must fail for its planted reason only):\n${l}")
    endif()
  endif()
endforeach()

# ---- 2. the clean twin passes ----------------------------------------------------------------------
string(REGEX REPLACE "[^\n]*// planted-only[^\n]*\n" "" clean "${source}")
string(REGEX REPLACE "([ \t]*)[^\n]*// clean: ([^\n]*)" "\\1\\2" clean "${clean}")
if(clean STREQUAL source)
  message(FATAL_ERROR "${name}: no '// planted-only' or '// clean: <code>' marker, so no clean twin")
endif()
set(twin "${WORK}/clean/${name}")
file(WRITE "${twin}" "${clean}")
execute_process(
  COMMAND "${CHECKER}" --cxx "${CXX}" --root "${ROOT}" --work "${WORK}/clean_work" "${twin}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("---- checker on the clean twin ${twin} (expected to pass) ----\n${out}${err}")
if(NOT rc STREQUAL "0")
  message(FATAL_ERROR "${name}: the clean twin does not pass (exit '${rc}'), so the file fails for more than its planted reason")
endif()
