# Many checks in one command, and their verdicts as JUnit XML (dlpverify suite, --junit):
# suite.sh says what each mode asserts. Included from CMakeLists.txt.
foreach(mode verification junit errors analyze refused resume)
  add_test(NAME cli.suite-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.suite-${mode} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
# Studies side by side: threaded, so the TSan build runs it too.
add_test(NAME cli.suite-parallel COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} parallel)
set_tests_properties(cli.suite-parallel PROPERTIES LABELS "cli;threaded" TIMEOUT 300)
