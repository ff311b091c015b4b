# --reference manufactured: manufactured.sh says what each mode asserts. Included from CMakeLists.txt.
foreach(mode orders slipped coupled refused)
  add_test(NAME cli.manufactured-${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/manufactured.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.manufactured-${mode} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
