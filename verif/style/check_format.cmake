# ctest style.clang_format: every C++ source of hls/, cmodel/ and verif/ is laid out as .clang-format
# says (clang-format --dry-run --Werror). The HLS-subset checker's planted and accepted kernels are
# test data and keep the shape their checks expect. -DFILES=a;b checks only those files (the
# self-test's misformatted file).
#   cmake -DCLANG_FORMAT=... -DROOT=<source dir> [-DFILES=...] -P check_format.cmake
if(NOT FILES)
  file(GLOB_RECURSE FILES LIST_DIRECTORIES false
       "${ROOT}/hls/*.hpp" "${ROOT}/cmodel/*.hpp" "${ROOT}/cmodel/*.cpp"
       "${ROOT}/verif/*.hpp" "${ROOT}/verif/*.cpp" "${ROOT}/verif/*.h")
  list(FILTER FILES EXCLUDE REGEX "/verif/hls_subset/(planted|accepted)/")
endif()
list(LENGTH FILES count)
if(count EQUAL 0)
  message(FATAL_ERROR "style: no C++ sources found under ${ROOT}")
endif()
set(bad "")
foreach(f IN LISTS FILES)
  execute_process(COMMAND ${CLANG_FORMAT} --style=file:${ROOT}/.clang-format --dry-run --Werror ${f}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    file(RELATIVE_PATH rel "${ROOT}" "${f}")
    list(APPEND bad "${rel}")
  endif()
endforeach()
if(bad)
  list(JOIN bad "\n  " listing)
  message(FATAL_ERROR "style: these files differ from .clang-format (run clang-format -i on them):\n  ${listing}")
endif()
message(STATUS "style: ${count} files follow .clang-format")
