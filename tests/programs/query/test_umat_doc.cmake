# docs/material.md must be what `interlock-query --markdown` prints now.
# cmake -DQUERY=... -DDOC=docs/material.md -DOUT=<scratch> -P test_umat_doc.cmake
execute_process(COMMAND ${QUERY} --markdown OUTPUT_FILE ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "interlock-query --markdown failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DOC} ${OUT} RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "${DOC} is out of date with the material table.\n"
    "Refresh it with:\n  ${QUERY} --markdown > ${DOC}\n(generated now: ${OUT})")
endif()
message(STATUS "${DOC} is up to date")
