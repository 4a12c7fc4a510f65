# src/io: the decks the programs read (test_bad_decks.py: each bad deck of interlock-history
# (label history) and interlock-fit (label fit) gives its message, exit status 1 and no file;
# CR LF and a byte order mark are accepted) and the CSV reader's unit suite (label fit: the fit's
# curves). (Without INTERLOCK_BUILD_PROGRAMS there are no programs and nothing to test here.)
# interlock_bad_deck_tests(AREA PROGRAM expected...): the test AREA_bad_decks_NAME of each
# NAME.expected (+ NAME.nml), run by PROGRAM.
function(interlock_bad_deck_tests area program)
  foreach(expected IN LISTS ARGN)
    get_filename_component(name ${expected} NAME_WE)
    add_test(NAME ${area}_bad_decks_${name}
      COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_bad_decks.py
              $<TARGET_FILE:${program}> ${expected})
    set_tests_properties(${area}_bad_decks_${name} PROPERTIES LABELS ${area} TIMEOUT 120)
  endforeach()
endfunction()

if(TARGET interlock-history)
  # Bad decks: tests/data/bad_decks/NAME.expected (+ NAME.nml; an .expected alone is a deck that
  # does not exist), and the decks too big or too binary for the source tree, written at configure
  # time by the same script (--generate). One test per deck.
  set(history_generated_decks ${CMAKE_CURRENT_BINARY_DIR}/bad_decks_generated)
  execute_process(COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_bad_decks.py
                          --generate ${history_generated_decks}
                  RESULT_VARIABLE history_generate_rc)
  if(NOT history_generate_rc EQUAL 0)
    message(FATAL_ERROR "test_bad_decks.py --generate ${history_generated_decks} failed "
      "(${history_generate_rc}): the generated bad decks cannot be tested")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
               ${CMAKE_CURRENT_LIST_DIR}/test_bad_decks.py)
  file(GLOB history_bad_decks CONFIGURE_DEPENDS ${INTERLOCK_TEST_DATA}/bad_decks/*.expected)
  file(GLOB history_bad_decks_generated ${history_generated_decks}/*.expected)
  interlock_bad_deck_tests(history interlock-history ${history_bad_decks}
                           ${history_bad_decks_generated})

  # Windows line ends (CR LF) are accepted: the same results as the LF deck.
  add_test(NAME history_bad_decks_crlf
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_bad_decks.py --crlf
            $<TARGET_FILE:interlock-history> ${PROJECT_SOURCE_DIR}/inputs/fig6.nml)
  set_tests_properties(history_bad_decks_crlf PROPERTIES LABELS history)

  # A UTF-8 byte order mark before the deck is accepted: the same results, the deck attribute is
  # the text without it.
  add_test(NAME history_bad_decks_bom
    COMMAND ${INTERLOCK_TEST_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_bad_decks.py --bom
            $<TARGET_FILE:interlock-history> ${PROJECT_SOURCE_DIR}/inputs/fig6.nml)
  set_tests_properties(history_bad_decks_bom PROPERTIES LABELS history)
endif()

if(TARGET interlock-fit)
  # The bad fit decks of tests/data/bad_fit_decks (NAME.nml + NAME.expected).
  file(GLOB fit_bad_decks CONFIGURE_DEPENDS ${INTERLOCK_TEST_DATA}/bad_fit_decks/*.expected)
  interlock_bad_deck_tests(fit interlock-fit ${fit_bad_decks})
  interlock_add_pfunit_suite(fit_csv LABEL fit TEST_SOURCES test_csv.pf
    LINK_LIBRARIES interlock_fit_core)
endif()
