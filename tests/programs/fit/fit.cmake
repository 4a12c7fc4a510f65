# interlock-fit (docs/fit.md): recovery of known parameters from curves computed by
# interlock-history (granite and the Table 5 concrete-bar set; without noise to 1e-6, with 2 %
# noise within two standard errors), the staged granite deck of inputs/fit (section 4.1.5's
# order; data generated at test time); an optimum on the law's limit theta_f = theta_0, inputs
# read as written, no file when the fitted deck cannot be written, the discretization check of
# the staged deck, 3D decks (a recovery on the azimuthal RIA, a circular slip path, a square
# path whose per-component abscissa is refused), curves that cannot be matched (noise on the
# abscissa), the files under faults (a read-only folder, a full disk, SIGINT between the
# renames, signals during the fit), and the unit suite of the solver. Label fit. (The bad fit
# decks and the CSV reader's suite are tests/io's.)
# (Without INTERLOCK_BUILD_PROGRAMS there is no interlock-fit and nothing to test here.)
if(NOT TARGET interlock-fit)
  return()
endif()
foreach(set granite table5)
  foreach(noise 0 0.02)
    add_test(NAME fit_recovery_${set}_noise_${noise}
      COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
              $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> recovery ${set} ${noise})
    set_tests_properties(fit_recovery_${set}_noise_${noise} PROPERTIES LABELS fit TIMEOUT 300)
  endforeach()
endforeach()
add_test(NAME fit_staged_granite
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
          $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> staged
          ${PROJECT_SOURCE_DIR}/inputs/fit/granite_staged.nml)
set_tests_properties(fit_staged_granite PROPERTIES LABELS fit TIMEOUT 300)
add_test(NAME fit_discretization_granite
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
          $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> discretization
          ${PROJECT_SOURCE_DIR}/inputs/fit/granite_staged.nml)
set_tests_properties(fit_discretization_granite PROPERTIES LABELS fit TIMEOUT 600)
# 3D: the shipped deck (the azimuthal RIA at 45 deg; its CSV checked against interlock-history),
# without and with 2 % noise, and a circular slip path, each fitted history equal to
# interlock-history's.
add_test(NAME fit_recovery_3d_granite
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
          $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> recovery3d
          ${PROJECT_SOURCE_DIR}/inputs/fit/granite_3d_45.nml)
set_tests_properties(fit_recovery_3d_granite PROPERTIES LABELS fit TIMEOUT 300)
add_test(NAME fit_recovery_3d_granite_noise_0.02
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
          $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> recovery3d
          ${PROJECT_SOURCE_DIR}/inputs/fit/granite_3d_45.nml 0.02)
set_tests_properties(fit_recovery_3d_granite_noise_0.02 PROPERTIES LABELS fit TIMEOUT 300)
add_test(NAME fit_circle_3d
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
          $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> circle)
set_tests_properties(fit_circle_3d PROPERTIES LABELS fit TIMEOUT 300)
foreach(mode files identifiability coupled inputs deckfail square noisy readonly enospc renames
        signals)
  add_test(NAME fit_${mode}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_fit.py
            $<TARGET_FILE:interlock-fit> $<TARGET_FILE:interlock-history> ${mode})
  # 77: skipped (no strace for the injected faults; root without setpriv)
  set_tests_properties(fit_${mode} PROPERTIES LABELS fit TIMEOUT 300 SKIP_RETURN_CODE 77)
endforeach()
# The unit suite of the solver (pFUnit).
interlock_add_pfunit_suite(fit_lm LABEL fit TEST_SOURCES test_lm.pf
  LINK_LIBRARIES interlock_fit_core)
