# ctest results.tool: tools/results.py writes a page into --out exactly as into docs/results/ (the
# marked block equal to the page's but for its provenance line), and refuses a file there that lacks
# its markers, with exit status 2, a message naming the file and the rule, and the file untouched.
#   cmake -DPYTHON=... -DSOURCE=<source dir> -DBUILD=<build dir> -DWORK=<scratch folder> -P check_results.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(tool ${SOURCE}/tools/results.py)

# A fresh page in an empty folder: the same lines as the committed page, but the provenance line.
execute_process(COMMAND ${PYTHON} ${tool} --out ${WORK} --only operation_counts ${BUILD}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "results.py --out failed (${rc}): ${err}")
endif()
file(STRINGS ${SOURCE}/docs/results/operation_counts.md want)
file(STRINGS ${WORK}/operation_counts.md got)
list(FILTER want EXCLUDE REGEX "^Printed by cig ")
list(FILTER got EXCLUDE REGEX "^Printed by cig ")
if(NOT want STREQUAL got)
  message(FATAL_ERROR "results: ${WORK}/operation_counts.md differs from docs/results/operation_counts.md")
endif()

# A file of the page's name without the markers is someone else's: refused and kept.
set(mine "# my notes, not a results page\n")
file(WRITE ${WORK}/culling.md "${mine}")
execute_process(COMMAND ${PYTHON} ${tool} --out ${WORK} --only culling ${BUILD}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(READ ${WORK}/culling.md kept)
if(NOT rc EQUAL 2 OR NOT err MATCHES "culling.md: markers:" OR NOT kept STREQUAL mine)
  message(FATAL_ERROR "results: an unmarked file must be refused with exit 2 and kept; got ${rc}: ${err}")
endif()
message(STATUS "results: --out writes the page as committed; an unmarked file is refused and kept")
