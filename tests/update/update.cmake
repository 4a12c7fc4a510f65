# src/update, the library's update (label core): its pFUnit suites, one per .pf file, the
# program-level suites against one-sided differences and the independent reference's steps,
# the README's example, and the bench's smoke runs (both run the library's update).

foreach(stem tangent closed_forms limits invariants
        reduction3d isotropy3d closed_forms3d tangent3d order3d
        kernels kernels3d update_input)
  interlock_add_core_suite(${stem})
endforeach()

# The 3D law in dual numbers (tests/update/oracle3d): an independent oracle of the derivatives
# the library writes out by hand (core_oracle3d).
add_library(interlock_oracle3d STATIC ${CMAKE_CURRENT_LIST_DIR}/oracle3d/interlock_dual.f90
  ${CMAKE_CURRENT_LIST_DIR}/oracle3d/interlock_plane_law_3d_dual.f90
  ${CMAKE_CURRENT_LIST_DIR}/oracle3d/interlock_update_3d_dual.f90)
target_link_libraries(interlock_oracle3d PUBLIC interlock::interlock)
target_compile_options(interlock_oracle3d PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(interlock_oracle3d PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_oracle3d)
target_include_directories(interlock_oracle3d PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/mod_oracle3d)
interlock_add_pfunit_suite(core_oracle3d LABEL core TEST_SOURCES test_oracle3d.pf
  LINK_LIBRARIES interlock_core_testlib interlock_oracle3d)

# SPEC D13 (a plane at s_kn = 0 exactly is closed for every derivative) and the 3D tangents
# the fuzzer found matching neither one-sided derivative (`interlock-fuzz --3d` at seeds 3 and
# 12345, --beyond-bound at 2 and 99): against one-sided differences.
interlock_add_suite(core_contact_kinks core test_contact_kinks.f90)

# The README's example, built and run (examples/).
interlock_add_suite(core_readme_example core ${PROJECT_SOURCE_DIR}/examples/readme_example.f90)

# The bench (docs/bench.md), on a tiny setting: it does not time itself here. interlock-bench
# exits non-zero when an update or the Newton iteration on s_N fails on a non-coarse step
# count, when the bilinear baseline does not reproduce the damage-only set, or when the
# work-precision reference is not converged. (bench/ is added after tests/: test the option,
# not the target.)
if(INTERLOCK_BUILD_BENCH)
  set(bench_out ${CMAKE_CURRENT_BINARY_DIR}/bench_smoke)
  file(MAKE_DIRECTORY ${bench_out})
  add_test(NAME core_bench_smoke COMMAND interlock-bench --quick --out ${bench_out})
  set_tests_properties(core_bench_smoke PROPERTIES TIMEOUT 120 LABELS core
    FIXTURES_SETUP bench_smoke_csv)
  # The profiler mode (bench/profile_updates.py runs it under callgrind), here with substepping
  # (full model, implicit, substep_tol 1e-3, one pass = 12000 updates): no update may fail.
  add_test(NAME core_bench_profile_substep COMMAND interlock-bench --profile 5 2 1 1e-3)
  set_tests_properties(core_bench_profile_substep PROPERTIES TIMEOUT 120 LABELS core
    PASS_REGULAR_EXPRESSION "calls: 12000; checksum [^;]+; failed updates: 0[\r\n]")
  # The tables of docs/bench.md are printed from the CSV files by the plot script.
  interlock_output_check(check EXPECT "\\| \\+wear \\(full model\\) \\| implicit \\| none \\|"
    "\\*granite\\*" "Observed order")
  add_test(NAME core_plot_work_precision_markdown
    COMMAND ${check} ${INTERLOCK_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/plot_work_precision.py
            ${bench_out} --markdown)
  set_tests_properties(core_plot_work_precision_markdown PROPERTIES TIMEOUT 60 LABELS core
    FIXTURES_REQUIRED bench_smoke_csv)
endif()
