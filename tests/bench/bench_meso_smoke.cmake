# Smoke test of entourage-bench-meso (ctest bench_meso_smoke): a 5-second run of the default
# scenario exits 0 and prints its table; a bad option exits 2. No timing is checked.
# Usage: cmake -DBENCH=<path to entourage-bench-meso> -DSCENARIO=<scenario file> -P bench_meso_smoke.cmake
execute_process(COMMAND ${BENCH} --scenario ${SCENARIO} --duration 5 --repeat 1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "entourage-bench-meso exited ${rc}:\n${out}\n${err}")
endif()
foreach(expected "seed 1" "5 s simulated" "all-micro " "micro inside, meso out " "saving: " "per vehicle-step: micro ")
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "entourage-bench-meso printed no \"${expected}\":\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${BENCH} --duration -1 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--duration")
  message(FATAL_ERROR "entourage-bench-meso --duration -1 exited ${rc} (expected 2 and a message):\n${err}")
endif()
