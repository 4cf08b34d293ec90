# One bounded fuzzing run (a ctest in the sanitizer build, or tools/fuzz.sh for long local runs):
# the seed files are copied into a fresh working corpus, then the libFuzzer target runs for SECONDS
# seconds. It fails on any crash, sanitizer report, leak, uncaught exception, an input slower than
# 10 s (a hang) or above 2 GiB of memory; libFuzzer writes the failing input into ARTIFACTS, which
# is what becomes a regression file in verif/bad_input/.
#   cmake -DFUZZER=<exe> -DSEEDS="a;b;dir/*.json" -DWORK=<dir> -DSECONDS=60 [-DDICT=<file>] [-DSUPPRESSIONS=<lsan file>]
#         -P run_fuzzer.cmake
file(REMOVE_RECURSE ${WORK}/corpus)
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
set(count 0)
foreach(pattern IN LISTS SEEDS)
  file(GLOB seeds LIST_DIRECTORIES false ${pattern})
  foreach(seed IN LISTS seeds)
    math(EXPR count "${count} + 1")
    get_filename_component(name ${seed} NAME)
    file(COPY_FILE ${seed} ${WORK}/corpus/seed_${count}_${name})
  endforeach()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "fuzz: no seed files match ${SEEDS}")
endif()
set(dict_option "")
if(DICT)
  set(dict_option -dict=${DICT})
endif()
# LeakSanitizer suppressions (a target whose library leaks on its own error paths: lsan_assimp.supp).
set(env_command "")
if(SUPPRESSIONS)
  set(env_command ${CMAKE_COMMAND} -E env LSAN_OPTIONS=suppressions=${SUPPRESSIONS})
endif()
execute_process(
  COMMAND ${env_command} ${FUZZER} ${dict_option} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048 -max_len=65536
          -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/ ${WORK}/corpus
  WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(GLOB found ${WORK}/artifacts/*)
  message(FATAL_ERROR "fuzz: ${FUZZER} failed (status ${rc}); inputs: ${found}")
endif()
