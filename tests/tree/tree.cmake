# Checks of the source tree and its docs: the layers (label core), no deferred-length function
# result on the UMAT's path (label umat), the docs' citations (label core).

# The layer check: every module uses only its own folder's and lower layers' modules, the
# general update path not the kernels, every source file is built (docs/architecture.md), and
# every Fortran test source lives in the folder of its layer and is built (docs/tests.md).
add_test(NAME core_layers
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_layers.py ${PROJECT_SOURCE_DIR})
set_tests_properties(core_layers PROPERTIES LABELS core)

# No function that a UMAT call runs returns a deferred-length character result (gfortran keeps
# its length in a static variable of the caller: a race; umat_omp's messages test shows it).
add_test(NAME umat_no_deferred_results
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_deferred_results.py
          ${PROJECT_SOURCE_DIR}/src/base ${PROJECT_SOURCE_DIR}/src/material
          ${PROJECT_SOURCE_DIR}/src/laws ${PROJECT_SOURCE_DIR}/src/update
          ${PROJECT_SOURCE_DIR}/src/api ${PROJECT_SOURCE_DIR}/umat)
set_tests_properties(umat_no_deferred_results PROPERTIES LABELS umat
  PASS_REGULAR_EXPRESSION " 0 functions with a deferred-length result")

# The docs cite only what exists (label core): every CTest name (against this tree's tests),
# path, CMake option, program and program option that README.md and docs/*.md name; the areas
# this configuration leaves out (calculix without INTERLOCK_CCX, mpi without deal.II or in a
# Debug tree) are named, so that their tests are not looked for (so this fragment comes last).
set(docs_unconfigured_areas)
if(NOT INTERLOCK_CCX)
  list(APPEND docs_unconfigured_areas calculix)
endif()
if(NOT TEST mpi_dealii_build)
  list(APPEND docs_unconfigured_areas mpi)
endif()
add_test(NAME core_docs
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_docs.py ${PROJECT_SOURCE_DIR}
          ${PROJECT_BINARY_DIR} ${CMAKE_CTEST_COMMAND} ${docs_unconfigured_areas})
set_tests_properties(core_docs PROPERTIES LABELS core)
