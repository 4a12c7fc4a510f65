# The independent reference implementation of the three-dimensional law (tests/reference3d,
# SPEC section 9): its validation against the 2D reference curves, section 9's properties, the
# figures of the 3D documentation, and a re-generated subset of tests/data/reference3d.
if(NOT DEFINED INTERLOCK_REFERENCE3D_PYTHON)
  set(INTERLOCK_REFERENCE3D_PYTHON /usr/bin/python3)
endif()
add_test(NAME reference3d_check
  COMMAND ${INTERLOCK_REFERENCE3D_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/reference3d/check_reference3d.py)
set_tests_properties(reference3d_check PROPERTIES LABELS core TIMEOUT 300)
