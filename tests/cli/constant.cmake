# The error constant as a gate (check --baseline, compare) and how sharp a check is (sharpness):
# constant.sh says what each mode asserts. Included from CMakeLists.txt.
foreach(mode baseline bad-baseline compare off-order sharpness)
  add_test(NAME cli.constant-${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/constant.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.constant-${mode} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
