# The independent reference implementation of the three-dimensional law (tests/update/reference3d,
# SPEC section 9): its validation against the 2D reference curves, section 9's properties, the
# figures of the 3D documentation, and a re-generated subset of tests/data/reference3d.
add_test(NAME core_reference3d
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/reference3d/check_reference3d.py)
set_tests_properties(core_reference3d PROPERTIES LABELS core TIMEOUT 300)

# The library's three-dimensional update against the reference's single steps.
interlock_add_suite(core_reference3d_steps core test_reference3d_steps.f90)
