# Install the build tree into a scratch prefix, then configure, build and run a consumer
# project that finds the package with find_package(interlock REQUIRED).
# cmake -DBUILD_DIR= -DCONFIG= -DPREFIX= -DCONSUMER_SOURCE= -DCONSUMER_BUILD= -DGENERATOR= -DFC=
#       -P test_umat_install.cmake
file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})
include(${CMAKE_CURRENT_LIST_DIR}/../support/install_prefix.cmake)
# pFUnit is for our tests only: nothing of it is installed with interlock.
file(GLOB_RECURSE pfunit_files ${PREFIX}/*PFUNIT* ${PREFIX}/*funit* ${PREFIX}/*gftl* ${PREFIX}/*fargparse*)
if(pfunit_files)
  message(FATAL_ERROR "pFUnit was installed with interlock: ${pfunit_files}")
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_Fortran_COMPILER=${FC} -DCMAKE_PREFIX_PATH=${PREFIX})
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
run(${CONSUMER_BUILD}/consumer)
run(${CONSUMER_BUILD}/consumer_umat)
