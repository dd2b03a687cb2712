# Smoke test of entourage-bench-director's paired comparison (ctest bench_director_smoke): one run
# of a play written with --verbose, then the same run paired with that output: the bench is
# deterministic, so nothing is gained or lost and McNemar's p is 1. Bad --paired uses exit 2.
# Usage: cmake -DBENCH=<path to entourage-bench-director> -DSCENARIO=<scenario with a play>
#              -DWORK=<scratch directory> -P bench_director_smoke.cmake
file(MAKE_DIRECTORY ${WORK})
set(before ${WORK}/bench_director_smoke_before.txt)
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 1 --first 3 --verbose
                RESULT_VARIABLE rc OUTPUT_FILE ${before} ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-director --verbose exited ${rc}:\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --runs 1 --first 3 --paired ${before}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-director --paired exited ${rc}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "paired with [^\n]*: gained 0, lost 0 \\(both done [01], both failed [01], not in it 0\\); McNemar's p = 1.000")
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
