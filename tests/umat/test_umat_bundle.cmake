# The single-file bundle compiles on its own with plain gfortran (warning-free under the
# project's warning set, -Werror) and links into the fixed-form legacy driver, which passes.
# cmake -DFC=gfortran -DBUNDLE=... -DDRIVER=legacy_driver.f -DWORK=<scratch> -P test_umat_bundle.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ ${ARGN}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc})")
  endif()
endfunction()
run(${FC} -std=f2008 -Wall -Wextra -Wimplicit-interface -Wimplicit-procedure -Werror -O1
    -c ${BUNDLE} -o bundle.o)
run(${FC} -Wall -Wextra -Werror -O1 -c ${DRIVER} -o driver.o)
run(${FC} driver.o bundle.o -o legacy_driver)
execute_process(COMMAND ${WORK}/legacy_driver WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "legacy driver: all checks passed")
  message(FATAL_ERROR "the legacy driver failed (${rc})")
endif()
