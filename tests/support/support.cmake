# The suites' shared helpers: the assertion layer of the program-level Fortran suites
# (interlock_assert.f90) and the helpers of the library's unit suites (test_core_support.f90:
# materials of the paper, drivers, finite differences, a portable RNG). The UMAT's interface
# (test_umat_interface.f90) is compiled into each suite that calls the UMAT; check_output.py is
# interlock_expect_output's verdict; interlock_run.cmake and install_prefix.cmake are included
# by the script tests that install the build tree.
add_library(interlock_assert STATIC ${CMAKE_CURRENT_LIST_DIR}/interlock_assert.f90)
set_target_properties(interlock_assert PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_assert)
target_include_directories(interlock_assert PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/mod_assert)
target_compile_options(interlock_assert PRIVATE ${INTERLOCK_FFLAGS})

add_library(interlock_core_testlib STATIC ${CMAKE_CURRENT_LIST_DIR}/test_core_support.f90)
target_link_libraries(interlock_core_testlib PUBLIC interlock::interlock PFUNIT::funit)
target_compile_options(interlock_core_testlib PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(interlock_core_testlib PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)
target_include_directories(interlock_core_testlib PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/mod_core_testlib)
