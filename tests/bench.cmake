# Smoke run of the benchmark on a tiny setting (it does not time itself): the program must run
# to the end and exit 0. It exits non-zero when an update or the Newton iteration on s_N fails
# on a non-coarse step count, when the bilinear baseline does not reproduce the damage-only set,
# or when the work-precision reference is not converged. (bench/ is added after tests/, so test
# for the option and the folder, not for the target.)
if(INTERLOCK_BUILD_BENCH AND EXISTS ${PROJECT_SOURCE_DIR}/bench/CMakeLists.txt)
  set(_bench_out ${CMAKE_CURRENT_BINARY_DIR}/bench_smoke)
  file(MAKE_DIRECTORY ${_bench_out})
  add_test(NAME bench_smoke COMMAND interlock-bench --quick --out ${_bench_out})
  set_tests_properties(bench_smoke PROPERTIES TIMEOUT 120 LABELS bench)
endif()
