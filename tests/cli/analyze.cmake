# dlpverify analyze (docs/analyze.md): runs written by the Python exchange example while converge
# drives it give converge's numbers, with and without a reference; check's verdict passes on them
# and fails on the slipped (first-order) copy; runs that differ in a field, their member count or
# end time are refused with one line; CSV runs, their members matched by an id column or by
# position. analyze.py says what each mode asserts. Debian's python3 with python3-h5py.
foreach(mode reference self check mismatch csv)
  add_test(NAME cli.analyze-${mode}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/analyze.py $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR} ${mode})
  set_tests_properties(cli.analyze-${mode} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
# Bad input of analyze's own options: exit 2, one line naming the option and the value.
expect_exit(analyze-bad-variable 2 --variable position analyze missing.h5 --variable position)
expect_exit(analyze-bad-order 2 --order -1 analyze missing.h5 --order -1)
expect_exit(analyze-bad-dt 2 --dt -0.1 analyze missing.csv --dt -0.1)
expect_exit(analyze-bad-expect-order 2 --expect-order 0 analyze missing.h5 --expect-order 0)
expect_exit(analyze-expect-order-needs-p 2 --expect-order e=3 analyze missing.h5 --expect-order e=3)
expect_exit(analyze-missing-run 2 missing.h5 "cannot be read" analyze missing.h5 missing2.h5 missing3.h5)
expect_exit(analyze-bad-variables-file 2 --variables ${CMAKE_CURRENT_SOURCE_DIR}/unknown-key.toml
            analyze missing.h5 --variables ${CMAKE_CURRENT_SOURCE_DIR}/unknown-key.toml)
# The worked example (examples/analyze): Heun's runs pass check's order 2, forward Euler's fail it
# with exit 1 (their fitted orders, 2.00 and 1.00, are in docs/analyze.md). The script runs as
# the README prints it, without `sh`: its git mode must keep it executable.
add_test(NAME cli.analyze-example
         COMMAND ${CMAKE_SOURCE_DIR}/examples/analyze/run.sh $<TARGET_FILE:dlpverify> ${CMAKE_CURRENT_BINARY_DIR}/analyze-heun)
add_test(NAME cli.analyze-example-euler
         COMMAND bash -c "sh \"$0\" \"$1\" \"$2\" --euler; test $? -eq 1" ${CMAKE_SOURCE_DIR}/examples/analyze/run.sh
                 $<TARGET_FILE:dlpverify> ${CMAKE_CURRENT_BINARY_DIR}/analyze-euler)
set_tests_properties(cli.analyze-example cli.analyze-example-euler PROPERTIES LABELS cli TIMEOUT 120)
