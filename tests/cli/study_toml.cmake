# Study files read as TOML (types checked per option), empty values refused, and options that do
# nothing in the chosen mode refused (issue 33). Included from CMakeLists.txt, where expect_exit()
# and ${small} are defined.
foreach(case unquoted unterminated empty-title empty-dt quiet-yes quiet-one dt-string empty-json empty-config
             empty-dt-typed empty-threads empty-baseline empty-bench-outer empty-equals runs)
  add_test(NAME cli.study-toml-${case} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/study_toml.sh ${case} $<TARGET_FILE:dlpverify>)
  set_tests_properties(cli.study-toml-${case} PROPERTIES LABELS cli)
endforeach()

# Options that do nothing in the mode the others choose: exit 2, one line naming the option and its value.
expect_exit(idle-levels-with-tolerances 2 --levels 3 converge ${small} --integrator cvode --tolerances 1e-3:1e-5 --levels 3)
expect_exit(idle-budget-fixed-levels 2 --budget 60 converge ${small} --levels 3 --budget 60)
expect_exit(idle-order-ci-fixed-levels 2 --order-ci 0.1 converge ${small} --order-ci 0.1)
expect_exit(idle-block-tol-without-adaptive 2 --block-tol w1=1e-6 stagger --dt 0.5 --block-tol w1=1e-6)
expect_exit(idle-tol-without-adaptive 2 --tol 1e-4 stagger --dt 0.5 --tol 1e-4)
expect_exit(idle-tolerances-per-decade 2 --tolerances-per-decade 2 converge ${small} --tolerances-per-decade 2)
expect_exit(idle-exec-timeout 2 --exec-timeout 5 converge ${small} --exec-timeout 5)
expect_exit(idle-method-without-cvode 2 --method bdf converge ${small} --integrator rk4 --method bdf)
expect_exit(idle-history-outputs 2 --history-outputs 7 converge ${small} --history-outputs 7)
expect_exit(idle-plot-relative 2 --plot-relative true converge ${small} --plot-relative)
expect_exit(idle-title-without-plot 2 --title T converge ${small} --title T)
expect_exit(idle-precision-title 2 --title T precision --case drag --outer 4 --title T)
# Commands without --json/--csv/--table, which expect_exit adds: the exit code and the line (on
# stderr, joined to the output expect_output.sh reads) only.
add_test(NAME cli.idle-analyze-plot-relative
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 2 "--plot-relative = true: does nothing without --plot"
                 -- bash -c "\"$0\" analyze a.h5 b.h5 c.h5 --plot-relative 2>&1" $<TARGET_FILE:dlpverify>)
add_test(NAME cli.idle-bench-events
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 2 "--bench-events = 1000: does nothing without --bench"
                 -- bash -c "\"$0\" compress --bench-events 1000 2>&1" $<TARGET_FILE:dlpverify>)
set_tests_properties(cli.idle-analyze-plot-relative cli.idle-bench-events PROPERTIES LABELS cli)
expect_exit(idle-proportionality 2 --expect-proportionality 1 check ${small} --expect-order 2 --expect-proportionality 1)
expect_exit(idle-baseline-by-tolerance 2 --baseline b.json
            check ${small} --integrator cvode --tolerances 1e-3:1e-5 --baseline b.json)
# A study file's key counts as given: its search budget, with the levels a typed option fixes.
expect_exit(idle-budget-from-study-file 2 --budget 60 converge --config ${CMAKE_CURRENT_SOURCE_DIR}/auto-budget.toml --levels 3)
