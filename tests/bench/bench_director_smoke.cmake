# Smoke test of entourage-bench-director (ctest bench_director_smoke): two runs of a play written
# with --verbose --trace on one thread, the same two on two threads (--jobs 2: the output and the
# traces are the same, byte for byte), then the same runs paired with the first output: the bench
# is deterministic, so nothing is gained or lost and McNemar's p is 1. Bad --paired and --jobs
# exit 2.
# Usage: cmake -DBENCH=<path to entourage-bench-director> -DSCENARIO=<scenario with a play>
#              -DWORK=<scratch directory> -P bench_director_smoke.cmake
file(MAKE_DIRECTORY ${WORK})
set(before ${WORK}/bench_director_smoke_before.txt)
set(threaded ${WORK}/bench_director_smoke_threaded.txt)
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 2 --first 3 --verbose --trace --jobs 1
                RESULT_VARIABLE rc OUTPUT_FILE ${before} ERROR_VARIABLE trace_one)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-director --verbose exited ${rc}:\n${trace_one}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 2 --first 3 --verbose --trace --jobs 2
                RESULT_VARIABLE rc OUTPUT_FILE ${threaded} ERROR_VARIABLE trace_two)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-director --jobs 2 exited ${rc}:\n${trace_two}")
endif()
file(READ ${before} one_thread)
file(READ ${threaded} two_threads)
if(NOT one_thread STREQUAL two_threads)
  message(FATAL_ERROR "two threads printed another output than one:\n${one_thread}\n---\n${two_threads}")
endif()
# The traces: written live on one thread, buffered per run on two, the same either way.
if(NOT trace_one MATCHES "trigger point 1 passed" OR NOT trace_one STREQUAL trace_two)
  message(FATAL_ERROR "the traces on one thread and on two differ, or are missing:\n${trace_one}\n---\n${trace_two}")
endif()
if(NOT one_thread MATCHES "run 3 seed 4 [^\n]*\nrun 4 seed 5 ")
  message(FATAL_ERROR "the two runs' lines are missing or out of order:\n${one_thread}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 1 --jobs -1 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--jobs wants a number")
  message(FATAL_ERROR "--jobs -1 exited ${rc} (expected 2 and a message):\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 2 --first 3 --jobs 2 --paired ${before}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-director --paired exited ${rc}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "paired with [^\n]*: gained 0, lost 0 \\(both done [012], both failed [012], not in it 0\\); McNemar's p = 1.000")
  message(FATAL_ERROR "the same run paired with itself flipped, or was not paired:\n${out}")
endif()
execute_process(COMMAND ${BENCH} --runs 1 --paired ${before} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--paired wants one --scenario")
  message(FATAL_ERROR "--paired without --scenario exited ${rc} (expected 2 and a message):\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 1 --paired ${WORK}/no_such_file.txt
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "cannot read")
  message(FATAL_ERROR "--paired with a missing file exited ${rc} (expected 2 and a message):\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 1 --paired ${SCENARIO}
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "has no run lines")
  message(FATAL_ERROR "--paired with a file without run lines exited ${rc} (expected 2 and a message):\n${err}")
endif()
