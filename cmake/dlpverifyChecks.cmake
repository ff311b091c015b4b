# Registers a project's verification studies as CTest tests, one line each, the way
# gtest_discover_tests registers GoogleTest cases (installed with dlpverify's CMake package):
#
#   dlpverify_add_check(NAME CONFIG study.toml [JUNIT report.xml] [ARGS option…])
#       `dlpverify check --config study.toml` as the test NAME;
#   dlpverify_add_suite(NAME FILES a.toml b.toml … [JUNIT report.xml] [ARGS option…])
#       `dlpverify suite a.toml b.toml …` as the test NAME.
#
# Relative paths are the calling CMakeLists.txt's folder's, and the test runs there, so that a
# study file's own relative paths (a tableau:FILE, an exec: program) resolve as in the source tree.
# The exit codes map onto CTest's outcomes: 0 passes, 5 (inconclusive: double precision could not
# decide) is reported as skipped (SKIP_RETURN_CODE), every other code fails.
# DLPVERIFY_EXECUTABLE is the installed command (set by dlpverifyConfig.cmake).

function(_dlpverify_add_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "JUNIT" "COMMAND;ARGS")
  set(command ${DLPVERIFY_EXECUTABLE} ${arg_COMMAND} ${arg_ARGS})
  if(arg_JUNIT)
    get_filename_component(junit "${arg_JUNIT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    list(APPEND command --junit "${junit}")
  endif()
  add_test(NAME ${name} COMMAND ${command} WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 5)
endfunction()

function(dlpverify_add_check name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "CONFIG;JUNIT" "ARGS")
  if(NOT arg_CONFIG)
    message(FATAL_ERROR "dlpverify_add_check(${name}): CONFIG study.toml is required")
  endif()
  get_filename_component(config "${arg_CONFIG}" ABSOLUTE)
  _dlpverify_add_test(${name} COMMAND check --config "${config}" JUNIT "${arg_JUNIT}" ARGS ${arg_ARGS})
endfunction()

function(dlpverify_add_suite name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "JUNIT" "FILES;ARGS")
  if(NOT arg_FILES)
    message(FATAL_ERROR "dlpverify_add_suite(${name}): FILES study.toml … is required")
  endif()
  set(files "")
  foreach(file ${arg_FILES})
    get_filename_component(file "${file}" ABSOLUTE)
    list(APPEND files "${file}")
  endforeach()
  _dlpverify_add_test(${name} COMMAND suite ${files} JUNIT "${arg_JUNIT}" ARGS ${arg_ARGS})
endfunction()
