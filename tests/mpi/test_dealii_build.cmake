# The deal.II example's build (fixture of the `mpi` tests): install this build tree into a
# scratch prefix, then configure and build examples/dealii against it, as a user would.
# cmake -DBUILD_DIR= -DPREFIX= -DSOURCE= -DBINARY= -DGENERATOR= -DDEAL_II_DIR= -P test_dealii_build.cmake
file(REMOVE_RECURSE ${PREFIX})
set(CONFIG Release)
include(${CMAKE_CURRENT_LIST_DIR}/../support/install_prefix.cmake)
run(${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${PREFIX} -DDEAL_II_DIR=${DEAL_II_DIR})
run(${CMAKE_COMMAND} --build ${BINARY})
