# interlock-history (label history; docs/history-output.md): every deck of inputs/ runs and its
# HDF5 file follows the layout contract (fixture chain "program writes HDF5" -> "Python checks
# it"); the reference curves of tests/data/reference are reproduced by the explicit and implicit
# schemes that computed them. (Without INTERLOCK_BUILD_PROGRAMS there is no interlock-history and
# nothing to test here.) The bad decks are tests/io's, the mixed-control solver's suite
# tests/driver's.
if(NOT TARGET interlock-history)
  return()
endif()
set(history_out ${CMAKE_CURRENT_BINARY_DIR}/history_out)
file(MAKE_DIRECTORY ${history_out})

file(GLOB history_decks CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/inputs/*.nml)
foreach(deck IN LISTS history_decks)
  get_filename_component(name ${deck} NAME_WE)
  add_test(NAME history_run_${name}
    COMMAND interlock-history --output-dir ${history_out} ${deck})
  set_tests_properties(history_run_${name} PROPERTIES FIXTURES_SETUP history_${name}
    LABELS history)
  add_test(NAME history_h5_${name}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_history_h5.py
            ${history_out}/${name}.h5)
  set_tests_properties(history_h5_${name} PROPERTIES FIXTURES_REQUIRED history_${name}
    LABELS history)
endforeach()

foreach(figure fig5 fig6 fig7 fig8 fig8_long fig9 fig10 fig11)
  add_test(NAME history_reference_${figure}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_reference.py
            $<TARGET_FILE:interlock-history> ${INTERLOCK_TEST_DATA}/reference
            ${CMAKE_CURRENT_BINARY_DIR}/history_reference ${figure})
  set_tests_properties(history_reference_${figure} PROPERTIES LABELS history)
endforeach()

# The derived-scale range docs/deck-format.md states is the one the deck check refuses by
# (bad deck derived_stiffness_beyond_bound: 2^-300 .. 2^300, the library's).
interlock_output_check(check EXPECT
  "s_0 = \\(1 - eta\\) s_c in \\[2\\^-300, 2\\^300\\] mm and\\s+K = sigma0 / s_0 in \\[2\\^-300, 2\\^300\\] MPa/mm")
add_test(NAME history_doc_derived_range
  COMMAND ${check} ${CMAKE_COMMAND} -E cat ${PROJECT_SOURCE_DIR}/docs/deck-format.md)
set_tests_properties(history_doc_derived_range PROPERTIES LABELS history)

# Mixed control under stress: tiny H_N, eta -> 1, tiny zeta0, huge steps, both schemes, with and
# without substepping, slip under constant sigma_N and both components traction-driven.
add_test(NAME history_stress
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_stress.py
          $<TARGET_FILE:interlock-history> ${CMAKE_CURRENT_BINARY_DIR}/history_stress)
set_tests_properties(history_stress PROPERTIES LABELS history TIMEOUT 300)

# Global Richardson extrapolation (&solver extrapolate = .true.): (a) on the Fig. 10 wear scene
# the extrapolated history converges at order > 1.7 and the plain one at ~1, and it is exactly
# composed of the two runs; (b) without wear (Fig. 5) it equals the plain history to round-off;
# a case that stops names the run that failed; (c) a deck with extrapolated cases (Fig. 12
# scene, zeta_0 sweep) follows the layout contract; (d) a one-step segment in which planes
# slide or wear is warned about.
foreach(mode wear nowear stopped preload jumps)
  add_test(NAME history_extrapolate_${mode}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_extrapolate.py
            $<TARGET_FILE:interlock-history> ${INTERLOCK_TEST_DATA}
            ${CMAKE_CURRENT_BINARY_DIR}/history_extrapolate_${mode} ${mode})
  set_tests_properties(history_extrapolate_${mode} PROPERTIES LABELS history TIMEOUT 300)
endforeach()
add_test(NAME history_run_fig12_extrapolated
  COMMAND interlock-history --output-dir ${history_out}
          ${INTERLOCK_TEST_DATA}/history/fig12_extrapolated.nml)
set_tests_properties(history_run_fig12_extrapolated PROPERTIES
  FIXTURES_SETUP history_fig12_extrapolated LABELS history)
add_test(NAME history_h5_fig12_extrapolated
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_history_h5.py
          ${history_out}/fig12_extrapolated.h5)
set_tests_properties(history_h5_fig12_extrapolated PROPERTIES
  FIXTURES_REQUIRED history_fig12_extrapolated LABELS history)

# newton_tol = 1e-15 on the concrete-bar cyclic pull-out: the history completes (the solver
# accepts a residual within the resolution of s where the tolerance asks for less).
add_test(NAME history_newton_tol_eps
  COMMAND interlock-history --output-dir ${history_out}
          ${INTERLOCK_TEST_DATA}/history/pullout_concrete_cyclic_tol_1e-15.nml)
set_tests_properties(history_newton_tol_eps PROPERTIES LABELS history TIMEOUT 300
  PASS_REGULAR_EXPRESSION "case 0001: completed" FAIL_REGULAR_EXPRESSION "stopped")

# --help documents the options and the exit status.
interlock_output_check(check EXPECT "--output-dir DIR" "--version" "Exit status:"
  "0  every case" "1  a deck was rejected" "2  every file was written"
  "iterations <= newton_max_iterations" "extrapolate = .true." "2 u\\(2n\\) - u\\(n\\)")
add_test(NAME history_help COMMAND ${check} $<TARGET_FILE:interlock-history> --help)
set_tests_properties(history_help PROPERTIES LABELS history)

# &output every and store (docs/deck-format.md): thinned rows and chosen datasets are the full
# run's, bitwise (plain and extrapolated, a sweep, a case that stops); the bad values are in
# tests/data/bad_decks (every_zero, every_wrong_type, store_nonsense, store_unknown_name).
foreach(mode every list stopped)
  add_test(NAME history_output_${mode}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_output.py
            $<TARGET_FILE:interlock-history> ${CMAKE_CURRENT_BINARY_DIR}/history_output_${mode}
            ${mode})
  set_tests_properties(history_output_${mode} PROPERTIES LABELS history TIMEOUT 120)
endforeach()

# Reliability (README "Reliability"): the output never replaces the deck or a file that
# is not an earlier result; a full disk (file-size limit; a 64 kB tmpfs where mounting is
# allowed, else skipped) ends with exit 1 and a message, no crash, no file; every catchable
# signal that ends the program (SIGPIPE of `| head -1` too) removes the temporary file (SIGKILL
# leaves it); an output name of 255 characters is written; a 2e6-step history keeps its peak
# memory below 64 MB (rows streamed to the file).
foreach(mode overwrite fulldisk tmpfs signals pipe longname memory)
  add_test(NAME history_reliability_${mode}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_reliability.py
            $<TARGET_FILE:interlock-history> ${PROJECT_SOURCE_DIR}/inputs/fig6.nml
            ${CMAKE_CURRENT_BINARY_DIR}/history_reliability_${mode} ${mode})
  set_tests_properties(history_reliability_${mode} PROPERTIES LABELS history TIMEOUT 600
    SKIP_RETURN_CODE 77)
endforeach()

# Usage errors of the programs: message and usage on stderr, status 2
# (interlock-history and interlock-fit: 1), no ERROR STOP or backtrace; --help and --version on stdout, status 0;
# nothing written into the working folder (interlock-bench needs --out).
# (interlock-fuzz is defined in stability.cmake, after this file: generator expressions resolve
# it at generate time.)
set(cli_programs history=$<TARGET_FILE:interlock-history> fit=$<TARGET_FILE:interlock-fit>
    query=$<TARGET_FILE:interlock_query> fuzz=$<TARGET_FILE:interlock-fuzz>)
if(INTERLOCK_BUILD_BENCH)
  list(APPEND cli_programs bench=$<TARGET_FILE:interlock-bench>)
endif()
add_test(NAME history_cli_usage
  COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_cli_usage.py
          ${CMAKE_CURRENT_BINARY_DIR}/cli_usage ${cli_programs})
set_tests_properties(history_cli_usage PROPERTIES LABELS history TIMEOUT 120)

# Three dimensions (SPEC section 9, docs/three-dimensions.md): the histories of
# tests/data/reference3d reproduced by decks with their protocol (granite, paper and azimuthal
# N_a = 3 RIAs, straight, square and circular paths, implicit and trapezoidal: 1e-10); constant
# sigma_N on two turns of a circle (held to the solver's tolerance at every step); a 3D deck with
# every azimuth 0 and T2 = 0 reproduces the 2D deck (1e-14); a 2D deck's HDF5 layout is the
# stored one (tests/data/layout); the shipped direction sweeps give the peak shears and spreads
# that SPEC section 9 quotes from an independent implementation; a history restarted from one
# of its rows (the strike components in &initial_state) continues it; the circle's lag and the
# induced anisotropy that docs/three-dimensions.md quotes; a &sweep over ria or n_azimuths gives
# each case the RIA it names.
foreach(mode reference circle reduction layout sweep restart scenes ria_sweep)
  add_test(NAME history_3d_${mode}
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_history_3d.py
            $<TARGET_FILE:interlock-history> ${INTERLOCK_TEST_DATA}
            ${CMAKE_CURRENT_BINARY_DIR}/history_3d_${mode} ${mode})
  set_tests_properties(history_3d_${mode} PROPERTIES LABELS history TIMEOUT 300)
endforeach()

# plot_history.py draws the 3D figures (slip path, traction and dilation against the slip length,
# the polar peak and residual shear of a direction sweep; the induced-anisotropy comparison
# along t2) from the shipped 3D decks' files, and the 2D figure from a 2D file.
add_test(NAME history_plot_3d
  COMMAND ${INTERLOCK_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/plot_history.py
          ${history_out}/granite_3d_sweep_az3.h5 ${history_out}/granite_3d_circle.h5
          ${history_out}/fig13.h5)
set_tests_properties(history_plot_3d PROPERTIES LABELS history
  FIXTURES_REQUIRED "history_granite_3d_sweep_az3;history_granite_3d_circle;history_fig13")
# The polar figure of several direction sweeps (docs/three-dimensions.md).
add_test(NAME history_plot_polar
  COMMAND ${INTERLOCK_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/plot_history.py --polar
          ${history_out}/granite_3d_sweep_paper.h5 ${history_out}/granite_3d_sweep_az3.h5
          ${history_out}/granite_3d_sweep_az6.h5 -o ${history_out}/granite_3d_polar.png)
set_tests_properties(history_plot_polar PROPERTIES LABELS history
  FIXTURES_REQUIRED "history_granite_3d_sweep_paper;history_granite_3d_sweep_az3;history_granite_3d_sweep_az6"
  PASS_REGULAR_EXPRESSION "granite_3d_polar.png")
add_test(NAME history_plot_3d_compare
  COMMAND ${INTERLOCK_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/plot_history.py
          ${history_out}/granite_3d_anisotropy.h5 --compare
          ${history_out}/granite_3d_anisotropy_virgin.h5 --axis t2
          -o ${history_out}/granite_3d_anisotropy_t2.png)
set_tests_properties(history_plot_3d_compare PROPERTIES LABELS history
  FIXTURES_REQUIRED "history_granite_3d_anisotropy;history_granite_3d_anisotropy_virgin")
