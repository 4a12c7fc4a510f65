# Shared by the install tests (test_umat_install.cmake, test_c_api_install.cmake,
# test_dealii_build.cmake): run(command...) (interlock_run.cmake), then the build tree BUILD_DIR
# (configuration CONFIG, Release by default) installed into PREFIX.
include(${CMAKE_CURRENT_LIST_DIR}/interlock_run.cmake)
if(NOT CONFIG)
  set(CONFIG Release)
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} --config ${CONFIG})
