# Users' Butcher tableaux (--integrator tableau:FILE, dlpverify tableau): tableau.sh says what each
# mode asserts. Included from CMakeLists.txt.
foreach(mode slipped passes json drag gas malformed)
  add_test(NAME cli.tableau-${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tableau.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.tableau-${mode} PROPERTIES LABELS cli TIMEOUT 60)
endforeach()
# Bad input in a study of a tableau that misses a condition is still one line: the warning waits
# for the first step.
expect_exit(tableau-bad-input-one-line 2 --dt 0.0003 check ${small} --expect-order 2 --dt 0.0003
            --integrator tableau:${CMAKE_SOURCE_DIR}/examples/tableaux/midpoint-slipped-c2.toml)
