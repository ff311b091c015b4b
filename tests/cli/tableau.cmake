# Users' Butcher tableaux (--integrator tableau:FILE, dlpverify tableau): tableau.sh says what each
# mode asserts. Included from CMakeLists.txt.
foreach(mode slipped passes json drag gas malformed)
  add_test(NAME cli.tableau-${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tableau.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.tableau-${mode} PROPERTIES LABELS cli TIMEOUT 60)
endforeach()
