# Suites of the core library (issue "The interface law as a library", item 7).
# Shared helpers (materials of the paper, drivers, finite differences, a portable RNG).
add_library(interlock_core_testlib STATIC test_core_support.f90)
target_link_libraries(interlock_core_testlib PUBLIC interlock::interlock interlock_assert)
target_compile_options(interlock_core_testlib PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(interlock_core_testlib PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)
target_include_directories(interlock_core_testlib PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)

function(interlock_add_core_suite name)
  interlock_add_suite(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE interlock_core_testlib)
  set_tests_properties(${name} PROPERTIES LABELS core)
endfunction()

interlock_add_core_suite(core_tangent test_tangent.f90 test_tangent_main.f90)
interlock_add_core_suite(core_closed_forms test_closed_forms.f90 test_closed_forms_main.f90)
interlock_add_core_suite(core_limits test_limits.f90 test_limits_main.f90)
interlock_add_core_suite(core_invariants test_invariants.f90 test_invariants_main.f90)
interlock_add_core_suite(core_mechanisms test_kinematics.f90 test_damage.f90 test_friction.f90
  test_wear.f90 test_geometry.f90 test_mechanisms_main.f90)
interlock_add_core_suite(core_kernels test_kernels.f90)
