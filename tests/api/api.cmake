# src/api, the library as a package (label umat: what a host links): install + find_package
# from a Fortran consumer project (tests/api/consumer), the C API from C and C++ programs built
# against an installed prefix (tests/api/c_api), and the symmetric tangent for hosts that
# symmetrize.

# --- cmake --install into a temporary prefix, then a consumer project with find_package.
add_test(NAME umat_install
  COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${PROJECT_BINARY_DIR} -DCONFIG=$<CONFIG>
    -DPREFIX=${CMAKE_CURRENT_BINARY_DIR}/install_test/prefix
    -DCONSUMER_SOURCE=${CMAKE_CURRENT_LIST_DIR}/consumer
    -DCONSUMER_BUILD=${CMAKE_CURRENT_BINARY_DIR}/install_test/consumer
    -DGENERATOR=${CMAKE_GENERATOR} -DFC=${CMAKE_Fortran_COMPILER}
    -P ${CMAKE_CURRENT_LIST_DIR}/test_umat_install.cmake)
set_tests_properties(umat_install PROPERTIES TIMEOUT 300 LABELS umat)

# --- The symmetric tangent for hosts that symmetrize (PROPS 20 tangent = 2): the interface
#     alone under traction control, Newton with the exact tangent, its symmetric part, the
#     library's symmetric tangent and two other candidates (a measurement: docs/calculix.md).
interlock_add_suite(umat_tangent_newton umat tangent_newton.f90)

# --- The C API (include/interlock.h, docs/c-api.md) from C and C++ programs built against an
#     installed prefix (tests/api/c_api): the fixture installs, builds them and exports the
#     histories of a 3D and a 2D deck; the tests replay them step by step, refuse garbage, run
#     4 threads against the serial update, and run the documentation's example.
find_program(INTERLOCK_TEST_CC NAMES cc gcc)
find_program(INTERLOCK_TEST_CXX NAMES c++ g++)
if(TARGET interlock-history AND INTERLOCK_TEST_CC AND INTERLOCK_TEST_CXX)
  set(c_api_dir ${CMAKE_CURRENT_BINARY_DIR}/c_api_test)
  add_test(NAME umat_c_api_install
    COMMAND ${CMAKE_COMMAND}
      -DBUILD_DIR=${PROJECT_BINARY_DIR} -DCONFIG=$<CONFIG> -DPREFIX=${c_api_dir}/prefix
      -DCONSUMER_SOURCE=${CMAKE_CURRENT_LIST_DIR}/c_api -DCONSUMER_BUILD=${c_api_dir}/consumer
      -DGENERATOR=${CMAKE_GENERATOR} -DCC=${INTERLOCK_TEST_CC} -DCXX=${INTERLOCK_TEST_CXX}
      -DEXAMPLE=${PROJECT_SOURCE_DIR}/examples/c_api_example.c
      -DHISTORY=$<TARGET_FILE:interlock-history> -DPYTHON=${INTERLOCK_TEST_PYTHON}
      -DDECK_3D=${PROJECT_SOURCE_DIR}/inputs/granite_3d_anisotropy.nml
      -DDECK_2D=${PROJECT_SOURCE_DIR}/inputs/fig5.nml -DOUT=${c_api_dir}/histories
      -P ${CMAKE_CURRENT_LIST_DIR}/test_c_api_install.cmake)
  set_tests_properties(umat_c_api_install PROPERTIES TIMEOUT 600 LABELS umat
    FIXTURES_SETUP c_api)
  interlock_output_check(check EXPECT
    "3D history: 1801 steps, dim 3, 60 STATEV: largest difference"
    "2D history: 2401 steps, dim 2, 22 STATEV" "all checks passed")
  add_test(NAME umat_c_api COMMAND ${check} ${c_api_dir}/consumer/test_c_api
    ${c_api_dir}/histories/granite_3d_anisotropy.txt ${c_api_dir}/histories/fig5.txt)
  interlock_output_check(check EXPECT "(?s)bitwise equal.*bitwise equal" "all checks passed")
  add_test(NAME umat_c_api_cxx COMMAND ${check} ${c_api_dir}/consumer/test_c_api_cxx
    ${c_api_dir}/histories/granite_3d_anisotropy.txt)
  add_test(NAME umat_c_api_example COMMAND ${CMAKE_COMMAND}
    -DDOC=${PROJECT_SOURCE_DIR}/docs/c-api.md -DSOURCE=${PROJECT_SOURCE_DIR}/examples/c_api_example.c
    -DPROGRAM=${c_api_dir}/consumer/c_api_example
    -P ${CMAKE_CURRENT_LIST_DIR}/test_c_api_example.cmake)
  set_tests_properties(umat_c_api umat_c_api_cxx umat_c_api_example PROPERTIES TIMEOUT 300
    LABELS umat FIXTURES_REQUIRED c_api)
endif()
