# pFUnit for the unit suites (tests only: find_package(interlock) never needs it).
#
# In this order:
#   1. an installed pFUnit 4 (find_package; CMAKE_PREFIX_PATH or PFUNIT_DIR);
#   2. the copy this build tree built earlier (<build>/_deps/pfunit-install);
#   3. built from source: INTERLOCK_PFUNIT_SOURCE (a local archive or an unpacked source tree)
#      when set, without any download; otherwise the pinned release INTERLOCK_PFUNIT_URL,
#      fetched with FetchContent and checked against INTERLOCK_PFUNIT_SHA256.
# The source is built and installed into the build tree at configure time, by its own CMake
# run (Release, SKIP_MPI, no self-tests): so pFUnit's flags are its own, its install rules and
# its CTestCustom.cmake stay out of this project, and it is built once per build tree.
set(INTERLOCK_PFUNIT_SOURCE "" CACHE STRING
  "pFUnit offline: a local archive (.tar, .tar.gz) or an unpacked source tree with its submodules")
# Upstream's release asset carries the submodules (gFTL, gFTL-shared, fArgParse); the archive
# GitHub makes of the tag does not, and pFUnit then tries git, which fails on a tarball.
set(INTERLOCK_PFUNIT_URL
  "https://github.com/Goddard-Fortran-Ecosystem/pFUnit/releases/download/v4.14.0/pFUnit-v4.14.0.tar"
  CACHE STRING "pFUnit's pinned release (used when neither an installed pFUnit nor INTERLOCK_PFUNIT_SOURCE)")
set(INTERLOCK_PFUNIT_SHA256 "" CACHE STRING
  "sha256 of the archive to use (INTERLOCK_PFUNIT_SOURCE, or INTERLOCK_PFUNIT_URL instead of the pinned one)")
# The pinned release asset's sha256, as Spack's builtin pfunit recipe pins pFUnit-v4.14.0.tar
# (not re-measured here: the build machines reach no network but Debian's archive).
set(INTERLOCK_PFUNIT_URL_SHA256 "3f5fcc79cf5f12ed08eb8e49aff23e0826243b14d4b2b2efee91ce823ac1749d"
  CACHE STRING "sha256 of INTERLOCK_PFUNIT_URL (the pinned release)")

find_package(Python COMPONENTS Interpreter REQUIRED)

set(interlock_pfunit_prefix ${PROJECT_BINARY_DIR}/_deps/pfunit-install)
find_package(PFUNIT 4 QUIET)
if(NOT PFUNIT_FOUND)
  find_package(PFUNIT 4 QUIET PATHS ${interlock_pfunit_prefix} NO_DEFAULT_PATH)
endif()

if(NOT PFUNIT_FOUND)
  include(FetchContent)
  set(hash_option)
  if(INTERLOCK_PFUNIT_SHA256)
    set(hash_option URL_HASH SHA256=${INTERLOCK_PFUNIT_SHA256})
  endif()
  if(INTERLOCK_PFUNIT_SOURCE AND IS_DIRECTORY "${INTERLOCK_PFUNIT_SOURCE}")
    set(pfunit_source_dir "${INTERLOCK_PFUNIT_SOURCE}")
    message(STATUS "pFUnit: building the source tree ${pfunit_source_dir}")
  else()
    if(INTERLOCK_PFUNIT_SOURCE)
      if(NOT EXISTS "${INTERLOCK_PFUNIT_SOURCE}")
        message(FATAL_ERROR "INTERLOCK_PFUNIT_SOURCE = '${INTERLOCK_PFUNIT_SOURCE}' does not exist: "
          "give a pFUnit archive or source tree (with its submodules)")
      endif()
      set(pfunit_url "${INTERLOCK_PFUNIT_SOURCE}")
      message(STATUS "pFUnit: building the local archive ${pfunit_url} (no download)")
    else()
      if(NOT INTERLOCK_PFUNIT_SHA256)
        if(NOT INTERLOCK_PFUNIT_URL_SHA256)
          message(FATAL_ERROR "pFUnit 4 not found, and no INTERLOCK_PFUNIT_SOURCE. Either\n"
            "  - point CMAKE_PREFIX_PATH (or PFUNIT_DIR) at an installed pFUnit 4,\n"
            "  - set INTERLOCK_PFUNIT_SOURCE to a pFUnit archive or source tree with submodules, or\n"
            "  - set INTERLOCK_PFUNIT_URL_SHA256 to the sha256 of ${INTERLOCK_PFUNIT_URL} to download it,\n"
            "  - or configure with -DINTERLOCK_BUILD_TESTS=OFF (the library needs no pFUnit).")
        endif()
        set(hash_option URL_HASH SHA256=${INTERLOCK_PFUNIT_URL_SHA256})
      endif()
      # One attempt, here, so that an offline machine fails at once and says what to do
      # (FetchContent's own download retries for minutes).
      get_filename_component(archive_name "${INTERLOCK_PFUNIT_URL}" NAME)
      set(pfunit_url ${PROJECT_BINARY_DIR}/_deps/${archive_name})
      if(NOT EXISTS ${pfunit_url})
        message(STATUS "pFUnit: downloading ${INTERLOCK_PFUNIT_URL}")
        file(DOWNLOAD "${INTERLOCK_PFUNIT_URL}" ${pfunit_url}.part STATUS download_status
          INACTIVITY_TIMEOUT 30 TIMEOUT 600)
        list(GET download_status 0 download_code)
        if(NOT download_code EQUAL 0)
          list(GET download_status 1 download_message)
          file(REMOVE ${pfunit_url}.part)
          message(FATAL_ERROR "pFUnit: the download of ${INTERLOCK_PFUNIT_URL} failed "
            "(${download_message}). Offline, set INTERLOCK_PFUNIT_SOURCE to a pFUnit archive or "
            "source tree, or CMAKE_PREFIX_PATH to an installed pFUnit.")
        endif()
        file(RENAME ${pfunit_url}.part ${pfunit_url})
      endif()
    endif()
    # FetchContent checks the archive against the checksum and unpacks it.
    FetchContent_Declare(interlock_pfunit URL "${pfunit_url}" ${hash_option}
      DOWNLOAD_EXTRACT_TIMESTAMP TRUE)
    FetchContent_GetProperties(interlock_pfunit)
    if(NOT interlock_pfunit_POPULATED)
      FetchContent_Populate(interlock_pfunit)
    endif()
    set(pfunit_source_dir "${interlock_pfunit_SOURCE_DIR}")
  endif()

  set(pfunit_build_dir ${PROJECT_BINARY_DIR}/_deps/pfunit-build)
  set(pfunit_log ${PROJECT_BINARY_DIR}/_deps/pfunit-build.log)
  message(STATUS "pFUnit: configure, build and install into ${interlock_pfunit_prefix} "
    "(once per build tree, a few minutes; log ${pfunit_log})")
  string(TIMESTAMP pfunit_start "%s")
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${pfunit_source_dir} -B ${pfunit_build_dir} -G ${CMAKE_GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_Fortran_COMPILER=${CMAKE_Fortran_COMPILER}
      -DCMAKE_INSTALL_PREFIX=${interlock_pfunit_prefix} -DPython_EXECUTABLE=${Python_EXECUTABLE}
      -DSKIP_MPI=YES -DSKIP_FHAMCREST=YES -DENABLE_TESTS=NO
    RESULT_VARIABLE rc OUTPUT_FILE ${pfunit_log} ERROR_FILE ${pfunit_log})
  if(rc EQUAL 0)
    execute_process(COMMAND ${CMAKE_COMMAND} --build ${pfunit_build_dir} --target install
      RESULT_VARIABLE rc OUTPUT_FILE ${pfunit_log}.build ERROR_FILE ${pfunit_log}.build)
    file(READ ${pfunit_log}.build build_output)
    file(APPEND ${pfunit_log} "${build_output}")
    file(REMOVE ${pfunit_log}.build)
  endif()
  if(NOT rc EQUAL 0)
    file(READ ${pfunit_log} pfunit_output)
    string(LENGTH "${pfunit_output}" length)
    if(length GREATER 4000)
      math(EXPR from "${length} - 4000")
      string(SUBSTRING "${pfunit_output}" ${from} 4000 pfunit_output)
    endif()
    message(FATAL_ERROR "pFUnit from ${pfunit_source_dir} failed to build (${rc}); "
      "the end of ${pfunit_log}:\n${pfunit_output}")
  endif()
  string(TIMESTAMP pfunit_end "%s")
  math(EXPR pfunit_seconds "${pfunit_end} - ${pfunit_start}")
  message(STATUS "pFUnit: built and installed in ${pfunit_seconds} s")
  find_package(PFUNIT 4 REQUIRED PATHS ${interlock_pfunit_prefix} NO_DEFAULT_PATH)
endif()
message(STATUS "pFUnit ${PFUNIT_VERSION} from ${PFUNIT_DIR}")
