# The deal.II example under MPI (label mpi; examples/dealii, docs/dealii.md). A fixture installs
# this build tree into a scratch prefix and builds the example against it (its own CMake
# project, as a user builds it); the cases of tests/mpi/test_dealii.py then run it with mpiexec.
# On by default in a Release tree (INTERLOCK_MPI_TESTS); they need deal.II 9.4 (MPI, p4est,
# PETSc) and an mpiexec: without them one test, mpi_dealii_absent, says what is missing and
# is reported as skipped.
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  set(_interlock_mpi_default ON)
else()
  set(_interlock_mpi_default OFF)
endif()
option(INTERLOCK_MPI_TESTS "the deal.II example's tests under MPI (label mpi)"
  ${_interlock_mpi_default})
if(NOT INTERLOCK_MPI_TESTS OR NOT TARGET interlock-history)
  return()
endif()

find_program(INTERLOCK_MPIEXEC NAMES mpiexec mpirun DOC "mpiexec for the mpi tests")
find_path(INTERLOCK_DEAL_II_DIR deal.IIConfig.cmake HINTS ENV DEAL_II_DIR
  PATH_SUFFIXES share/cmake/deal.II lib/cmake/deal.II cmake/deal.II
  DOC "the folder of deal.IIConfig.cmake, for the mpi tests")
set(mpi_missing "")
if(NOT INTERLOCK_MPIEXEC)
  string(APPEND mpi_missing "no mpiexec; ")
endif()
if(NOT INTERLOCK_DEAL_II_DIR)
  string(APPEND mpi_missing "no deal.II (deal.IIConfig.cmake); ")
endif()
if(mpi_missing)
  message(WARNING "interlock: the deal.II example's tests (label mpi) are skipped: "
    "${mpi_missing}scripts/ensure_packages.sh installs deal.II and OpenMPI")
  add_test(NAME mpi_dealii_absent
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_dealii.py absent
            --reason "${mpi_missing}")
  set_tests_properties(mpi_dealii_absent PROPERTIES LABELS mpi SKIP_RETURN_CODE 77)
  return()
endif()

set(mpi_work ${CMAKE_CURRENT_BINARY_DIR}/dealii)
add_test(NAME mpi_dealii_build
  COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${PROJECT_BINARY_DIR} -DPREFIX=${mpi_work}/prefix
    -DSOURCE=${PROJECT_SOURCE_DIR}/examples/dealii -DBINARY=${mpi_work}/build
    -DGENERATOR=${CMAKE_GENERATOR} -DDEAL_II_DIR=${INTERLOCK_DEAL_II_DIR}
    -P ${CMAKE_CURRENT_LIST_DIR}/test_dealii_build.cmake)
set_tests_properties(mpi_dealii_build PROPERTIES LABELS mpi TIMEOUT 900
  FIXTURES_SETUP dealii_example)

# OpenMPI refuses to run as root unless told (CI runs as root); np 4 on 2 cores needs
# oversubscription, and waiting processes that yield leave the cores to the others.
set(mpi_environment OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1)
# (tests/mpi/test_dealii.py runs the example with one BLAS thread per process: see there.)
foreach(case shear partition restart gmres pullout_partition pullout_restart)
  add_test(NAME mpi_dealii_${case}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_dealii.py ${case}
      --example ${mpi_work}/build/interlock_dealii --mpiexec ${INTERLOCK_MPIEXEC}
      --work ${mpi_work}/${case} --history $<TARGET_FILE:interlock-history>
      --deck ${PROJECT_SOURCE_DIR}/examples/dealii/direct_shear_45.nml)
  set_tests_properties(mpi_dealii_${case} PROPERTIES LABELS mpi TIMEOUT 900 PROCESSORS 2
    ENVIRONMENT "${mpi_environment}" FIXTURES_REQUIRED dealii_example)
endforeach()
