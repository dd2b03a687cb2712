# Smoke test of entourage-bench-catchups (ctest bench_catchups_smoke): a short whole road and two
# short window drives exit 0 and print both sets of figures, the same byte for byte with the drives
# on one thread and on two (--jobs); so do transparent probes on a short whole road and one drive of
# one; a bad option exits 2. No figure is checked.
# Usage: cmake -DBENCH=<path to entourage-bench-catchups> -DSCENARIO=<scenario file> -P bench_catchups_smoke.cmake
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --length 12000 --margin 2000 --warmup 400 --duration 120
                        --ego-every 5 --drives 2 --drive-duration 60 --jobs 1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-catchups exited ${rc}:\n${out}\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --length 12000 --margin 2000 --warmup 400 --duration 120
                        --ego-every 5 --drives 2 --drive-duration 60 --jobs 2
                RESULT_VARIABLE rc OUTPUT_VARIABLE threaded ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out STREQUAL threaded)
  message(FATAL_ERROR "entourage-bench-catchups --jobs 2 exited ${rc} or printed another output than one thread:\n"
                      "${out}\n---\n${threaded}\n${err}")
endif()
execute_process(COMMAND ${BENCH} --jobs -1 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--jobs")
  message(FATAL_ERROR "entourage-bench-catchups --jobs -1 exited ${rc} (expected 2 and a message):\n${err}")
endif()
foreach(expected "whole road: " "the ego stand-in's drivers on the whole road: " "window drive, seed   1"
                 "window drive, seed   2"
                 "the ego stand-in's window drives: " "catch-ups against the moving-observer prediction: passive "
                 "at the rear edge: in " "their space-mean speed: " "flow of its direction in the window: "
                 "window against the whole road: ")
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "entourage-bench-catchups printed no \"${expected}\":\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${BENCH} --ego-every 0 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--ego-every")
  message(FATAL_ERROR "entourage-bench-catchups --ego-every 0 exited ${rc} (expected 2 and a message):\n${err}")
endif()
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --probe-kph 100 --length 12000 --margin 2000 --warmup 400
                        --duration 320 --drives 1 --drive-duration 60
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-catchups --probe-kph 100 exited ${rc}:\n${out}\n${err}")
endif()
foreach(expected "transparent probes at 100 km/h" "the relations over the vehicles around the probes"
                 "window drives of a transparent probe at 100 km/h" "the probe's window drives: 1, "
                 "catch-ups against the moving-observer prediction: passive ")
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "entourage-bench-catchups --probe-kph 100 printed no \"${expected}\":\n${out}")
  endif()
endforeach()
string(FIND "${out}" "ego stand-in's drivers on the whole road" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "entourage-bench-catchups --probe-kph put the ego stand-in's drivers on the whole road:\n${out}")
endif()
execute_process(COMMAND ${BENCH} --probe-kph 0 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--probe-kph")
  message(FATAL_ERROR "entourage-bench-catchups --probe-kph 0 exited ${rc} (expected 2 and a message):\n${err}")
endif()
