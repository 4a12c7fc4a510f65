# Shared by the install tests (test_umat_install.cmake, test_c_api_install.cmake): run(command...)
# runs a command, prints it with its output and fails the test when it fails; then the build
# tree BUILD_DIR (configuration CONFIG, Release by default) is installed into PREFIX.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ ${ARGN}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc})")
  endif()
endfunction()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} --config ${CONFIG})
