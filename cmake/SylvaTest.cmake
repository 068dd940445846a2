# SylvaTest.cmake — how a test joins the suite: every ctest test is registered by
# sylva_add_test() as <area>.<case> with labels from one list, so `ctest -L unit` stays fast and
# any one test can run alone (`ctest -R '^unit\.sky\.'`: each TEST_CASE of a harness executable
# is a test of its own, sylva_add_test_cases).
#
# Labels:
#   unit        the core's own tests and the command line's contract; seconds in all
#   plugin      a plugin's model and the plugin through the host
#   image       renders compared with refimages/
#   crosscheck  sylva's verification mode against POV-Ray
#   faults      allocation-failure tests (one run per allocation)
#   slow        more than ~10 s in a Release build; also carries its area's label
#   fuzz        short runs of the fuzz targets (only with -DSYLVA_FUZZ=ON)
#   ztv         visibility maps (`sylva ztv`), against gdal_viewshed and known geometry
#   mpi         render and ztv split between the ranks of an MPI job (mpirun on this machine)
#
# A test that cannot run here (no POV-Ray, no shared data) exits 77 and ctest reports it as
# skipped, never as passed.

set(SYLVA_TEST_LABELS unit plugin image crosscheck faults slow fuzz ztv mpi)
set(SYLVA_TEST_SKIP_CODE 77)
set(SYLVA_SHARED_DATA_DIR "${CMAKE_SOURCE_DIR}/../shared/data" CACHE PATH
    "The shared data folder (DEMs, L-parser corpus) that tests registered NEEDS_SHARED_DATA read; they skip when it is absent")

# sylva_add_test(AREA area CASE case COMMAND command [args...] LABELS label...
#                [NEEDS_SHARED_DATA] [TIMEOUT seconds] [ENVIRONMENT VAR=value...]
#                [PASS_REGULAR_EXPRESSION regex] [FIXTURES_SETUP name...] [FIXTURES_REQUIRED name...])
# Registers the ctest test <area>.<case> (area may itself be dotted: plugin.tree_lsystem).
# NEEDS_SHARED_DATA hands the test SYLVA_SHARED_DATA_DIR in its environment; the test skips
# (exit 77) when that folder is missing. TIMEOUT defaults to 60 s for unit tests and 300 s for
# the others.
function(sylva_add_test)
  set(flags NEEDS_SHARED_DATA)
  set(one AREA CASE TIMEOUT PASS_REGULAR_EXPRESSION)
  set(many COMMAND LABELS ENVIRONMENT FIXTURES_SETUP FIXTURES_REQUIRED)
  cmake_parse_arguments(PARSE_ARGV 0 T "${flags}" "${one}" "${many}")
  if(T_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "sylva_add_test: unexpected arguments ${T_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required AREA CASE COMMAND LABELS)
    if(NOT T_${required})
      message(FATAL_ERROR "sylva_add_test(${T_AREA}.${T_CASE}): ${required} is required")
    endif()
  endforeach()
  set(name ${T_AREA}.${T_CASE})
  if(NOT name MATCHES "^[a-z0-9_]+(\\.[a-z0-9_]+)+$")
    message(FATAL_ERROR "sylva_add_test: '${name}' is not <area>.<case> in lower case, digits and _")
  endif()
  foreach(label ${T_LABELS})
    if(NOT label IN_LIST SYLVA_TEST_LABELS)
      message(FATAL_ERROR "sylva_add_test(${name}): label '${label}' is not one of ${SYLVA_TEST_LABELS}")
    endif()
  endforeach()
  if(NOT T_TIMEOUT)
    if("unit" IN_LIST T_LABELS)
      set(T_TIMEOUT 60)
    else()
      set(T_TIMEOUT 300)
    endif()
  endif()
  # Code under the sanitizers runs several times slower: every limit three times as long.
  if(SYLVA_SANITIZE)
    math(EXPR T_TIMEOUT "${T_TIMEOUT} * 3")
  endif()
  if(T_NEEDS_SHARED_DATA)
    list(APPEND T_ENVIRONMENT "SYLVA_SHARED_DATA_DIR=${SYLVA_SHARED_DATA_DIR}")
  endif()

  # The command's words are taken one by one from ARGV and passed as bracket arguments: a word
  # may hold an unmatched ']' (a message fragment such as "in (0, 1]"), which a CMake list
  # would not keep apart from the next word.
  set(words "")
  set(in_command FALSE)
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE ${last})
    set(word "${ARGV${i}}")
    if(word IN_LIST flags OR word IN_LIST one OR word IN_LIST many)
      string(COMPARE EQUAL "${word}" COMMAND in_command)
    elseif(in_command)
      string(APPEND words " [==[${word}]==]")
    endif()
  endforeach()
  cmake_language(EVAL CODE "add_test(NAME ${name} COMMAND ${words})")
  set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
                       SKIP_RETURN_CODE ${SYLVA_TEST_SKIP_CODE})
  foreach(property ENVIRONMENT PASS_REGULAR_EXPRESSION FIXTURES_SETUP FIXTURES_REQUIRED)
    if(T_${property})
      set_tests_properties(${name} PROPERTIES ${property} "${T_${property}}")
    endif()
  endforeach()
endfunction()

# sylva_add_test_cases(AREA area TARGET executable SOURCE file.c LABELS label...
#                      [SHARED_DATA_CASES case...] [other sylva_add_test options])
# registers one test <area>.<case> per TEST_CASE(case) of the harness's TEST_LIST in SOURCE, run
# as `executable case`, so a case added to the file is a ctest test at the next configure. The
# SHARED_DATA_CASES are registered NEEDS_SHARED_DATA.
function(sylva_add_test_cases)
  cmake_parse_arguments(PARSE_ARGV 0 C "" "AREA;TARGET;SOURCE" "SHARED_DATA_CASES")
  get_filename_component(source ${C_SOURCE} ABSOLUTE)
  file(STRINGS ${source} lines REGEX "TEST_CASE\\([a-z0-9_]+\\)")
  string(REGEX MATCHALL "TEST_CASE\\([a-z0-9_]+\\)" cases "${lines}")
  if(NOT cases)
    message(FATAL_ERROR "sylva_add_test_cases: ${C_SOURCE} lists no TEST_CASE")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source})
  foreach(c ${cases})
    string(REGEX REPLACE "TEST_CASE\\(([a-z0-9_]+)\\)" "\\1" case "${c}")
    set(shared)
    if(case IN_LIST C_SHARED_DATA_CASES)
      set(shared NEEDS_SHARED_DATA)
      list(REMOVE_ITEM C_SHARED_DATA_CASES ${case})
    endif()
    sylva_add_test(AREA ${C_AREA} CASE ${case} COMMAND ${C_TARGET} ${case} ${shared} ${C_UNPARSED_ARGUMENTS})
  endforeach()
  if(C_SHARED_DATA_CASES)
    message(FATAL_ERROR "sylva_add_test_cases: ${C_SOURCE} has no TEST_CASE ${C_SHARED_DATA_CASES}")
  endif()
endfunction()

# sylva_check_headers(TARGET name FOLDERS folder...) builds, as the object library TARGET (part
# of the default build), one generated .c per header of each src/core/<folder>/ that includes
# that header alone, twice (the second time through its include guard): a header that needs
# another included before it, or lacks its guard, fails the build naming it.
function(sylva_check_headers)
  cmake_parse_arguments(PARSE_ARGV 0 H "" "TARGET" "FOLDERS")
  set(sources "")
  foreach(folder ${H_FOLDERS})
    file(GLOB headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/core/${folder}/*.h)
    foreach(header ${headers})
      get_filename_component(name ${header} NAME_WE)
      set(source ${CMAKE_CURRENT_BINARY_DIR}/${H_TARGET}/${folder}_${name}.c)
      file(CONFIGURE OUTPUT ${source} CONTENT
           "/* generated: ${folder}/${name}.h compiles alone */\n#include \"${folder}/${name}.h\"\n#include \"${folder}/${name}.h\"\n")
      list(APPEND sources ${source})
    endforeach()
  endforeach()
  add_library(${H_TARGET} OBJECT ${sources})
  target_link_libraries(${H_TARGET} PRIVATE sylva_core)
endfunction()
