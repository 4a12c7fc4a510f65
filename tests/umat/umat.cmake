# The UMAT (label umat): the UMAT against the library (serial and threaded), bad input,
# PNEWDT, the single-file bundle with a fixed-form legacy driver, the replay deck of a local
# failure and the thin-layer entry.

# The UMAT's interface, for the suites that call it.
set(umat_interface ${INTERLOCK_TEST_SUPPORT}/test_umat_interface.f90)

# --- The UMAT against the library; bad input; PNEWDT.
interlock_add_pfunit_suite(umat LABEL umat TEST_SOURCES test_umat.pf
  OTHER_SOURCES ${umat_interface} LINK_LIBRARIES interlock_umat)
target_include_directories(umat PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)
# The rejections must also be reported: one line each, naming element, point and the property.
interlock_expect_output(umat EXPECT
  "interlock UMAT: element 7, point 3 \\(material 'TEST', increment 1\\): PROPS\\(4\\): property 'eta' = 0 is inadmissible: admissible 0 < +eta < +1"
  "NPROPS = 8 is inadmissible"
  "NSTATV = 21 is inadmissible"
  "NTENS = 4 is inadmissible: admissible NTENS = 2 \\(2D cohesive element: 1 normal, 2 shear\\) or 3"
  "diverged global iteration: DSTRAN = \\(NaN, 0\\) mm is not finite or takes the end of the increment beyond \\|s_N\\|, \\|s_T\\| <= 1000000 mm"
  "PNEWDT 0.25 asks to retry the increment cut back to a quarter \\(automatic incrementation\\). with fixed increments the host cannot cut back and stops"
  "the separation at the start of the increment STRAN = \\(NaN, 0\\) mm is inadmissible: admissible \\|s_N\\|, \\|s_T\\| <= 1000000 mm"
  "STATEV\\(1\\) = -0.1 \\(damage of plane 1\\) is inadmissible: admissible 0 <= damage <= 1 \\[-\\]"
  "STRESS\\(1\\) = NaN on entry is inadmissible")
set_tests_properties(umat PROPERTIES FAIL_REGULAR_EXPRESSION "ERROR STOP|Encountered 1 or more failures")
# pFUnit writes this folder's processed suites into <build>/tests/umat, so the suite `umat` is
# built in that folder (<build>/tests/umat/umat), not beside the others.
set_target_properties(umat PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/umat)

# --- The UMAT for 3D cohesive elements (NTENS = 3): the 2D UMAT with s_T2 = 0, the 3D update
#     on 3D histories, bad 3D input (each rejection's message is checked here too).
interlock_add_pfunit_suite(umat_3d LABEL umat TEST_SOURCES test_umat_3d.pf
  OTHER_SOURCES ${umat_interface} LINK_LIBRARIES interlock_umat)
target_include_directories(umat_3d PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)
interlock_expect_output(umat_3d EXPECT
  "PROPS\\(21\\): property 'ria' = 2 is inadmissible: admissible ria an integer from 0 to 1"
  "PROPS\\(21\\): property 'ria' = NaN is inadmissible"
  "PROPS\\(22\\): property 'n_azimuths' = 0 is inadmissible: admissible n_azimuths an integer from 1 to 6"
  "NSTATV = 28 is inadmissible: admissible NSTATV >= 60 for a 3D interface \\(the 3D law\\) with a RIA of 7 planes"
  "STATEV\\(24\\) = NaN \\(frictional_slip_strike of plane 2\\) is inadmissible"
  "STRAN = \\(0, 0, NaN\\) mm is inadmissible: admissible \\|s_N\\|, \\|s_T1\\|, \\|s_T2\\| <= 1000000 mm"
  "PROPS\\(21\\): property 'ria' = 1 is inadmissible with a 2D element \\(NTENS = 2\\)")
set_tests_properties(umat_3d PROPERTIES FAIL_REGULAR_EXPRESSION "ERROR STOP|Encountered 1 or more failures")

# --- An admissible frictional slip of 1e150 mm on a stiff interface: the 2D and 3D UMAT and
#     the thin layer return finite values (a fuzzed 3D state too).
interlock_add_suite(umat_huge_slip umat test_umat_huge_slip.f90 ${umat_interface})
target_link_libraries(umat_huge_slip PRIVATE interlock_umat)
target_include_directories(umat_huge_slip PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)

# --- Many threads at once give the serial numbers.
# (gfortran has OpenMP; the Debug flags leave out -fcheck=recursion, whose static flag per
# procedure is not thread-safe: see CMakeLists.txt.)
find_package(OpenMP REQUIRED COMPONENTS Fortran)
interlock_add_pfunit_suite(umat_omp LABEL umat TEST_SOURCES test_umat_omp.pf
  OTHER_SOURCES ${umat_interface} LINK_LIBRARIES interlock_umat OpenMP::OpenMP_Fortran)
set_tests_properties(umat_omp PROPERTIES ENVIRONMENT "OMP_THREAD_LIMIT=4")
# --- The single-file bundle (umat/CMakeLists.txt writes it; the tests need Python, so it is
#     there).
# (a) built here with the project's flags, linked with the legacy driver and nothing else.
add_executable(umat_legacy_driver ${CMAKE_CURRENT_LIST_DIR}/legacy_driver.f
               ${INTERLOCK_UMAT_BUNDLE})
add_dependencies(umat_legacy_driver interlock_umat_bundle)
set_target_properties(umat_legacy_driver PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_umat_legacy_driver)
set_source_files_properties(${INTERLOCK_UMAT_BUNDLE} PROPERTIES
  GENERATED TRUE COMPILE_OPTIONS "${INTERLOCK_FFLAGS}")
# F77-style host code: no -std=f2008 (old-style CHARACTER*80) and an implicit interface.
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/legacy_driver.f PROPERTIES COMPILE_OPTIONS
  "-Wall;-Wextra;$<$<CONFIG:Debug>:-fcheck=all;-ffpe-trap=invalid,zero,overflow;-finit-real=snan;-g>")
add_test(NAME umat_legacy_driver COMMAND umat_legacy_driver)
set_tests_properties(umat_legacy_driver PROPERTIES LABELS umat
  PASS_REGULAR_EXPRESSION "legacy driver: all checks passed" FAIL_REGULAR_EXPRESSION "FAIL")
# (b) what a user does: gfortran on the bundle alone (warning-free, -Werror), then the driver.
add_test(NAME umat_bundle
  COMMAND ${CMAKE_COMMAND}
    -DFC=${CMAKE_Fortran_COMPILER} -DBUNDLE=${INTERLOCK_UMAT_BUNDLE}
    -DDRIVER=${CMAKE_CURRENT_LIST_DIR}/legacy_driver.f
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/bundle_standalone
    -P ${CMAKE_CURRENT_LIST_DIR}/test_umat_bundle.cmake)
set_tests_properties(umat_bundle PROPERTIES TIMEOUT 120 LABELS umat)

# --- A local failure writes a replay deck (INTERLOCK_REPLAY_DIR); interlock-history replays it
#     and stops with the same reason (2D and 3D).
interlock_add_suite(umat_replay umat ${umat_interface} test_umat_replay.f90)
target_link_libraries(umat_replay PRIVATE interlock_umat)
set(umat_replay_dir ${CMAKE_CURRENT_BINARY_DIR}/umat_replay_decks)
file(MAKE_DIRECTORY ${umat_replay_dir})
set_tests_properties(umat_replay PROPERTIES
  ENVIRONMENT "INTERLOCK_REPLAY_DIR=${umat_replay_dir}"
  FIXTURES_SETUP umat_replay_deck)
interlock_expect_output(umat_replay EXPECT "unstable on small sub-increments"
  "test_umat_replay: [0-9]+ checks, 0 failed")
if(TARGET interlock-history)
  # the 2D UMAT's deck (element 5), and the 3D UMAT's (element 6: strike components, s_T2 and
  # the azimuths in it)
  foreach(replay "umat_history_replay;e5_p2_k3;s_T = 0.01 mm"
                 "umat_history_replay_3d;e6_p1_k3;s_T2 = 0.007 mm")
    list(GET replay 0 name)
    list(GET replay 1 deck)
    list(GET replay 2 target)
    # (exit status 2: the file is written, the case stopped)
    interlock_output_check(check STATUS 2 EXPECT "${target} at the end of the step"
      "unstable on small sub-increments" ABSENT "completed")
    add_test(NAME ${name}
      COMMAND ${check} $<TARGET_FILE:interlock-history> --output-dir ${umat_replay_dir}
              ${umat_replay_dir}/interlock_replay_${deck}.nml)
    set_tests_properties(${name} PROPERTIES LABELS umat FIXTURES_REQUIRED umat_replay_deck)
  endforeach()
endif()

# --- A near-integer value of an integer-valued property is refused with the digits that show
#     why (6.0000000001, 6 + 1 ulp), not rounded to the bound (the 3D UMAT and the thin layer).
add_executable(umat_near_integer_message ${CMAKE_CURRENT_LIST_DIR}/umat_near_integer_message.f90
               ${umat_interface})
target_link_libraries(umat_near_integer_message PRIVATE interlock_umat interlock::interlock)
target_compile_options(umat_near_integer_message PRIVATE ${INTERLOCK_FFLAGS})
set_target_properties(umat_near_integer_message PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod_umat_near_integer_message)
# (the thin-layer entry's module)
target_include_directories(umat_near_integer_message PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)
add_test(NAME umat_near_integer_message COMMAND umat_near_integer_message)
set_tests_properties(umat_near_integer_message PROPERTIES LABELS umat)
interlock_expect_output(umat_near_integer_message EXPECT "'n_azimuths' = 6.0000000001 is inadmissible"
  "'n_azimuths' = 6.000000000000001 is inadmissible" "'scheme' = 2.9999999999 is inadmissible"
  "'normal_axis' = 1.0000000001 is inadmissible" "umat_near_integer_message: 4 of 4 calls refused")

# --- The thin-layer entry for hosts without cohesive elements (CalculiX).
interlock_add_pfunit_suite(umat_layer LABEL umat TEST_SOURCES test_umat_layer.pf
  LINK_LIBRARIES interlock_umat)
target_include_directories(umat_layer PRIVATE ${PROJECT_BINARY_DIR}/umat/mod_umat)
interlock_expect_output(umat_layer EXPECT
  "layer PROPS\\(1\\): 'h' = 0 is inadmissible: admissible 1e-12 <= h <= 1e\\+12"
  "layer PROPS\\(2\\): 'e_other' = -5 is inadmissible"
  "layer PROPS\\(3\\): 'normal_axis' = 4 is inadmissible: admissible 1, 2 or 3"
  "layer PROPS\\(4\\): 'slip_axis' = 3 is inadmissible"
  "layer PROPS\\(8\\) = interlock PROPS\\(4\\): property 'eta' = 1.5 is inadmissible"
  "layer PROPS\\(24\\) = interlock PROPS\\(20\\): property 'tangent' = 3 is inadmissible"
  "NPROPS = 12 is inadmissible: admissible 13 <= NPROPS <= 26"
  "inadmissible with NTENS = 4"
  "diverged global iteration: DSTRAN\\(3\\) = \\+?Inf"
  "warning: element 9, point 4 \\(material 'LAYER', increment 1\\): the strain of component 3 = -0.3, which does not involve normal_axis = 1"
  "NSTATV = 29 is inadmissible for the thin layer: admissible NSTATV = 28 \\(the law's state\\) or NSTATV >= 34 \\(also the layer's separation and traction, STATEV 29-34\\)")
set_tests_properties(umat_layer PROPERTIES FAIL_REGULAR_EXPRESSION "ERROR STOP|Encountered 1 or more failures")

