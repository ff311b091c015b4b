# Many checks in one command, and their verdicts as JUnit XML (dlpverify suite, --junit):
# suite.sh says what each mode asserts. Included from CMakeLists.txt.
foreach(mode verification junit errors analyze refused)
  add_test(NAME cli.suite-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.suite-${mode} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
