# Numerical stability under hard cases (label stability): the stability matrix, the replay-deck
# test and the fuzzer (tests/stability/fuzz). The tools (random generator, mixed control,
# invariants) are shared.
add_library(interlock_stability_tools STATIC ${CMAKE_CURRENT_LIST_DIR}/test_stability_tools.f90)
set_target_properties(interlock_stability_tools PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_stability_tools)
target_include_directories(interlock_stability_tools PUBLIC
  ${CMAKE_CURRENT_BINARY_DIR}/mod_stability_tools)
target_link_libraries(interlock_stability_tools PUBLIC interlock::interlock)
target_compile_options(interlock_stability_tools PRIVATE ${INTERLOCK_FFLAGS})

interlock_add_suite(stability_matrix stability test_stability_matrix.f90)
target_link_libraries(stability_matrix PRIVATE interlock_stability_tools)
# Writes no file; `stability_matrix --doc docs/stability.md` (from the
# repository root) regenerates the documented one.
set_tests_properties(stability_matrix PROPERTIES
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} TIMEOUT 600)

# The fuzzer: CTest runs 1e5 updates with a fixed seed; a long run is
# `interlock-fuzz --seed 7 --updates 10000000`. Failing inputs are written as replay decks in
# the build tree.
add_executable(interlock-fuzz ${INTERLOCK_TEST_SUPPORT}/test_umat_interface.f90
               ${CMAKE_CURRENT_LIST_DIR}/fuzz/fuzz_fd_check.f90
               ${CMAKE_CURRENT_LIST_DIR}/fuzz/fuzz_3d.f90
               ${CMAKE_CURRENT_LIST_DIR}/fuzz/interlock_fuzz.f90)
target_link_libraries(interlock-fuzz PRIVATE interlock_stability_tools interlock::interlock
  interlock_umat interlock_cli)
target_compile_options(interlock-fuzz PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(interlock-fuzz PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_interlock_fuzz)
# (the thin-layer entry's module, for --garbage)
target_include_directories(interlock-fuzz PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/fuzz_decks)
add_test(NAME stability_fuzz
  COMMAND interlock-fuzz --updates 100000 --seed 1 --deck-dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz_decks
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(stability_fuzz PROPERTIES TIMEOUT 600 LABELS stability)
# Garbage through the UMAT entries (the 2D UMAT, the thin layer with NTENS 6 and 4 in both
# hosts' PNEWDT conventions), in every argument the host passes: outputs untouched, or finite;
# PNEWDT as it came or a request. In the Debug build any FP trap (invalid, zero, overflow)
# fails the test.
add_test(NAME stability_fuzz_garbage COMMAND interlock-fuzz --garbage 20000 --seed 3)
set_tests_properties(stability_fuzz_garbage PROPERTIES TIMEOUT 600 LABELS stability
  PASS_REGULAR_EXPRESSION "--garbage: seed 3, [0-9]+ UMAT calls \\(NTENS 2 and 3\\), [0-9]+ rejected, failures 0\n  thin layer \\(NTENS 6 and 4, Abaqus and CalculiX\\): [0-9]+ calls"
  FAIL_REGULAR_EXPRESSION "FAIL|ERROR STOP|Floating-point exception")
# Seed 1: its call 25008 garbles a 3D layer point's NTENS from 6 to 4, so the layer runs the 2D
# law and writes the 2D law's 22 slots and the layer's 4 (the slots after them are the host's,
# garbage included): the fuzzer counts the slots of the NTENS the entry is given.
add_test(NAME stability_fuzz_garbage_ntens_garbled COMMAND interlock-fuzz --garbage 30000 --seed 1)
set_tests_properties(stability_fuzz_garbage_ntens_garbled PROPERTIES TIMEOUT 600 LABELS stability
  PASS_REGULAR_EXPRESSION "--garbage: seed 1, [0-9]+ UMAT calls \\(NTENS 2 and 3\\), [0-9]+ rejected, failures 0\n"
  FAIL_REGULAR_EXPRESSION "FAIL|ERROR STOP|Floating-point exception")

# The three-dimensional update (interlock_update_3d): random materials with azimuths, random
# 3D histories, garbage separations, garbled materials and scheme codes; status codes only,
# never a NaN; the tangent against finite differences every 10 updates. In the Debug build any
# FP trap fails the test.
add_test(NAME stability_fuzz_3d COMMAND interlock-fuzz --3d 50000 --seed 5)
set_tests_properties(stability_fuzz_3d PROPERTIES TIMEOUT 600 LABELS stability
  PASS_REGULAR_EXPRESSION "--3d: seed 5, [0-9]+ materials .*failures 0;"
  FAIL_REGULAR_EXPRESSION "FAIL|ERROR STOP|Floating-point exception")
# A longer run: its update 686270 puts a wearing plane's wear-equation root within round-off of
# the point where the plane loses contact (zeta_0 = 3e-4 N/mm, implicit), where the tangent
# must come from the contact side (docs/model.md, the wear root at the contact kink).
add_test(NAME stability_fuzz_3d_long COMMAND interlock-fuzz --3d 700000 --seed 20261126)
set_tests_properties(stability_fuzz_3d_long PROPERTIES TIMEOUT 1200 LABELS stability
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/fuzz_decks
  PASS_REGULAR_EXPRESSION "--3d: seed 20261126, [0-9]+ materials .*failures 0;"
  FAIL_REGULAR_EXPRESSION "FAIL|ERROR STOP|Floating-point exception")
# The same with garbage separations of any finite magnitude (beyond separation_bound too) and
# garbage angles (theta0, phi): the update must refuse them or return finite values, the
# material's preparation must refuse them without a trap.
add_test(NAME stability_fuzz_3d_beyond_bound
  COMMAND interlock-fuzz --3d 20000 --seed 6 --beyond-bound)
set_tests_properties(stability_fuzz_3d_beyond_bound PROPERTIES TIMEOUT 600 LABELS stability
  PASS_REGULAR_EXPRESSION "--3d: seed 6, [0-9]+ materials .*failures 0;"
  FAIL_REGULAR_EXPRESSION "FAIL|ERROR STOP|Floating-point exception")

# Updates the fuzzers found with a tangent that matched no finite difference, replayed from
# their exact inputs and checked as the fuzzer checks them
# (tests/stability/fuzz/fuzz_fd_check.f90).
interlock_add_suite(stability_fuzz_cases stability fuzz/fuzz_fd_check.f90 fuzz/test_fuzz_cases.f90)

# Replay decks: write one for a failing update, read it back, re-run it.
interlock_add_suite(stability_replay stability test_stability_replay.f90)
set_tests_properties(stability_replay PROPERTIES
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} FIXTURES_SETUP stability_replay_deck)
# The point-history program reproduces the failure of a replay deck written by the fuzzer
# (the explicit scheme with substepping on a stiff case, where the chained tangent grows
# without bound and the update says so): exit status 2, "stopped at step 1".
if(TARGET interlock-history)
  add_test(NAME stability_history_replay
    COMMAND interlock-history ${INTERLOCK_TEST_DATA}/stability_replay_overflow.nml
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(stability_history_replay PROPERTIES LABELS stability
    FAIL_REGULAR_EXPRESSION "completed" PASS_REGULAR_EXPRESSION "stopped at step 1")
  # A fuzzed 3D step with very fast wear under error-controlled substepping completes (it
  # stopped after 100000 sub-increments when a rejection or a failed wear equation took the
  # size below the smallest controlled one, where it never grew back).
  add_test(NAME stability_history_replay_fast_wear
    COMMAND interlock-history ${INTERLOCK_TEST_DATA}/stability_fast_wear_substeps.nml
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(stability_history_replay_fast_wear PROPERTIES LABELS stability
    TIMEOUT 120 PASS_REGULAR_EXPRESSION "case 0001: completed"
    FAIL_REGULAR_EXPRESSION "stopped")
endif()
