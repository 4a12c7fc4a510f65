# src/driver (label history: interlock-history's mixed-control solver): the solver unit-tested
# in Fortran. (Without INTERLOCK_BUILD_PROGRAMS there is no driver.)
if(TARGET interlock_driver)
  interlock_add_suite(history_mixed_control history test_history_mixed_control.f90)
  target_link_libraries(history_mixed_control PRIVATE interlock_driver)
endif()
