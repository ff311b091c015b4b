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
# Diagonally implicit tableaux (examples/tableaux/sdirk*.toml) of orders 2, 3 and 4 pass a
# manufactured study on drag at their order through ARKStep; their twins with b_1 + 1e-3 and
# b_s − 1e-3 (tests/cli/tableaux/*-slipped-b.toml: Σ b_i c_i = 1/2 broken, order 1) fail it.
foreach(method 2:sdirk2-alexander 3:sdirk3-crouzeix 4:sdirk4-crouzeix)
  string(REPLACE ":" ";" parts ${method})
  list(GET parts 0 order)
  list(GET parts 1 file)
  expect_exit(tableau-${file} 0 "" "" check --case drag --outer 4 --reference manufactured --expect-order ${order}
              --integrator tableau:${CMAKE_SOURCE_DIR}/examples/tableaux/${file}.toml)
  expect_exit(tableau-${file}-slipped 1 "" "" check --case drag --outer 4 --reference manufactured --expect-order ${order}
              --integrator tableau:${CMAKE_CURRENT_SOURCE_DIR}/tableaux/${file}-slipped-b.toml)
endforeach()
