# Smoke run of the benchmark on a tiny setting (it does not time itself): the program must run
# to the end and exit 0. It exits non-zero when an update or the Newton iteration on s_N fails
# on a non-coarse step count, when the bilinear baseline does not reproduce the damage-only set,
# or when the work-precision reference is not converged. (bench/ is added after tests/, so test
# for the option and the folder, not for the target.)
if(INTERLOCK_BUILD_BENCH AND EXISTS ${PROJECT_SOURCE_DIR}/bench/CMakeLists.txt)
  set(_bench_out ${CMAKE_CURRENT_BINARY_DIR}/bench_smoke)
  file(MAKE_DIRECTORY ${_bench_out})
  add_test(NAME bench_smoke COMMAND interlock-bench --quick --out ${_bench_out})
  set_tests_properties(bench_smoke PROPERTIES TIMEOUT 120 LABELS bench
    FIXTURES_SETUP bench_smoke_csv)
  # The profiler mode (bench/profile_updates.py runs it under callgrind), here with substepping
  # (full model, implicit, substep_tol 1e-3, one pass = 12000 updates): no update may fail.
  add_test(NAME bench_profile_substep
    COMMAND interlock-bench --profile 5 2 1 1e-3)
  set_tests_properties(bench_profile_substep PROPERTIES TIMEOUT 120 LABELS bench
    PASS_REGULAR_EXPRESSION "calls: 12000; checksum [^;]+; failed updates: 0[\r\n]")
  # The tables of docs/bench.md are printed from the CSV files by the plot script.
  if(EXISTS /usr/bin/python3)
    add_test(NAME bench_markdown
      COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/plot_work_precision.py
              ${_bench_out} --markdown)
    set_tests_properties(bench_markdown PROPERTIES TIMEOUT 60 LABELS bench
      FIXTURES_REQUIRED bench_smoke_csv
      PASS_REGULAR_EXPRESSION "\\| \\+wear \\(full model\\) \\| implicit \\| none \\|.*\\*granite\\*.*Observed order")
  endif()
endif()
