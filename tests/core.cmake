# Suites of the core library (issue "The interface law as a library", item 7), as pFUnit tests.
# Shared helpers (materials of the paper, drivers, finite differences, a portable RNG).
add_library(interlock_core_testlib STATIC test_core_support.f90)
target_link_libraries(interlock_core_testlib PUBLIC interlock::interlock PFUNIT::funit)
target_compile_options(interlock_core_testlib PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(interlock_core_testlib PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)
target_include_directories(interlock_core_testlib PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)

function(interlock_add_core_suite name)
  interlock_add_pfunit_suite(${name} TEST_SOURCES ${ARGN}
    LINK_LIBRARIES interlock_core_testlib LABELS core)
endfunction()

interlock_add_core_suite(core_tangent test_tangent.pf)
interlock_add_core_suite(core_closed_forms test_closed_forms.pf)
interlock_add_core_suite(core_limits test_limits.pf)
interlock_add_core_suite(core_invariants test_invariants.pf)
interlock_add_core_suite(core_mechanisms test_kinematics.pf test_damage.pf test_friction.pf
  test_wear.pf test_geometry.pf)
interlock_add_core_suite(core_kernels test_kernels.pf)
interlock_add_core_suite(core_update_input test_update_input.pf)
