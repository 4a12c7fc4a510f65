# The paper's pull-out test (section 4.2) in CalculiX, coarse mesh (10 mm elements), to 5.2 mm:
# added only when the project is configured with -DINTERLOCK_CCX=<ccx linked with interlock>
# (bash scripts/build_calculix.sh prints its path). Label calculix. The model, the assertions
# and the measured convergence: docs/calculix_pullout.md.
if(NOT INTERLOCK_CCX)
  return()
endif()
add_test(NAME calculix_pullout_coarse
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/test_calculix_pullout.py
          ${INTERLOCK_CCX} ${CMAKE_CURRENT_BINARY_DIR}/calculix_pullout_coarse)
set_tests_properties(calculix_pullout_coarse PROPERTIES LABELS calculix TIMEOUT 900
  PROCESSORS 2)
if(TEST calculix_build)
  set_tests_properties(calculix_pullout_coarse PROPERTIES FIXTURES_REQUIRED calculix_binary)
endif()
