# The C API's fixture: install the build tree into a scratch prefix, build the C and C++
# consumer (tests/api/c_api) against it, run interlock-history on a 3D and a 2D deck and export
# the histories for the C and C++ tests (tests/api/c_api/export_history.py).
# cmake -DBUILD_DIR= -DCONFIG= -DPREFIX= -DCONSUMER_SOURCE= -DCONSUMER_BUILD= -DGENERATOR=
#       -DCC= -DCXX= -DEXAMPLE= -DHISTORY= -DPYTHON= -DDECK_3D= -DDECK_2D= -DOUT=
#       -P test_c_api_install.cmake
file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD} ${OUT})
file(MAKE_DIRECTORY ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/../support/install_prefix.cmake)
if(NOT EXISTS ${PREFIX}/include/interlock.h)
  message(FATAL_ERROR "include/interlock.h is not installed")
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_C_COMPILER=${CC} -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_PREFIX_PATH=${PREFIX} -DEXAMPLE=${EXAMPLE})
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
foreach(deck ${DECK_3D} ${DECK_2D})
  run(${HISTORY} --output-dir ${OUT} ${deck})
  get_filename_component(name ${deck} NAME_WE)
  run(${PYTHON} ${CONSUMER_SOURCE}/export_history.py ${OUT}/${name}.h5 0001 ${OUT}/${name}.txt)
endforeach()
