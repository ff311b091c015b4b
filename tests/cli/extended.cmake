# --precision extended: extended.sh says what each mode asserts. Included from CMakeLists.txt.
foreach(mode floor tableau refused)
  add_test(NAME cli.extended-${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/extended.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.extended-${mode} PROPERTIES LABELS cli TIMEOUT 180)
endforeach()
