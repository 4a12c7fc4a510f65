# The example of docs/c-api.md: the page holds examples/c_api_example.c verbatim, and the
# program built from it against the installed library (tests/api/c_api) runs.
# cmake -DDOC= -DSOURCE= -DPROGRAM= -P test_c_api_example.cmake
file(READ ${SOURCE} source)
file(READ ${DOC} doc)
string(FIND "${doc}" "```c\n${source}```" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${DOC} does not hold ${SOURCE} verbatim in a ```c block")
endif()
execute_process(COMMAND ${PROGRAM} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${rc})")
endif()
