# src/programs/query, interlock-query (label umat: it prints the UMAT's PROPS and STATEV
# tables) and docs/material.md, which is what it prints.
add_test(NAME umat_doc
  COMMAND ${CMAKE_COMMAND} -DQUERY=$<TARGET_FILE:interlock_query>
    -DDOC=${PROJECT_SOURCE_DIR}/docs/material.md -DOUT=${CMAKE_CURRENT_BINARY_DIR}/material.md
    -P ${CMAKE_CURRENT_LIST_DIR}/test_umat_doc.cmake)
set_tests_properties(umat_doc PROPERTIES LABELS umat)
interlock_output_check(check EXPECT "PROPS +name" "(?m)^4 +eta +- +required +0 < +eta < +1"
  "(?m)^19 +wear +- +1 " "(?m)^20 +tangent +- +1 " "(?m)^22 +n_azimuths +- +3 " "NPROPS from 9 to 22")
add_test(NAME umat_query_props COMMAND ${check} $<TARGET_FILE:interlock_query> --props)
interlock_output_check(check EXPECT "STATEV +name" "(?m)^13 +theta +1 \\(-theta_0\\) +rad"
  "(?m)^22 +initialized +- " "NSTATV >= 22" "(?m)^28 +friction_traction_strike +3 \\(\\+theta_0\\) +MPa"
  "NSTATV >= 28")
add_test(NAME umat_query_statev COMMAND ${check} $<TARGET_FILE:interlock_query> --statev)
set_tests_properties(umat_query_props umat_query_statev PROPERTIES LABELS umat)
add_test(NAME umat_query_bad_option COMMAND interlock_query --no-such-option)
set_tests_properties(umat_query_bad_option PROPERTIES LABELS umat WILL_FAIL TRUE)
