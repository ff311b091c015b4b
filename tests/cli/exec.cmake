# Your own integrator (--integrator exec:COMMAND, docs/exchange.md): each way a user's program can
# fail ends the study with exit 3 and one line naming the level, the command and what went wrong,
# with the program's last stderr lines; nothing is written. Included from CMakeLists.txt, where
# expect_exit() and ${small} are defined. bad_integrator.py fails in the mode it is given.
set(bad "exec:/usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/bad_integrator.py")
set(said "exit is what I do")  # the program's last stderr line, quoted in the error line

expect_exit(exec-exit-status 3 "exited with status 7" "${said}" check ${small} --expect-order 2 --integrator "${bad} exit {input} {output}")
expect_exit(exec-no-output 3 "wrote no output file" "none is what I do" check ${small} --expect-order 2 --integrator "${bad} none {input} {output}")
expect_exit(exec-garbage-output 3 "is not an HDF5 file" "garbage is what I do" check ${small} --expect-order 2
            --integrator "${bad} garbage {input} {output}")
expect_exit(exec-missing-field 3 "has no field /fields/vz" "missing is what I do" check ${small} --expect-order 2
            --integrator "${bad} missing {input} {output}")
expect_exit(exec-wrong-length 3 "/fields/x has length 255, expected 256" "short is what I do" check ${small} --expect-order 2
            --integrator "${bad} short {input} {output}")
expect_exit(exec-non-finite 3 "/fields/vx has a non-finite value at member 3" "nan is what I do" check ${small} --expect-order 2
            --integrator "${bad} nan {input} {output}")
expect_exit(exec-float32 3 "/fields/x is not float64" "float32 is what I do" check ${small} --expect-order 2
            --integrator "${bad} float32 {input} {output}")
expect_exit(exec-not-found 3 "cannot start no-such-program-dlpverify" "No such file" converge ${small}
            --integrator "exec:no-such-program-dlpverify {input} {output}")
expect_exit(exec-in-shell 3 "exited with status 5" "said in a shell" converge ${small} --exec-shell
            --integrator "exec:echo said in a shell >&2 && exit 5")  # (a ";" would split the CMake list)
# The level is named by its step: the case's coarsest (drag: dt = 5e-4 s, 20 steps).
expect_exit(exec-names-level 3 "level dt = 0.0005 s (20 steps)" "" converge ${small}
            --integrator "${bad} exit {input} {output}")
# A program that returns its input unchanged runs, and a check of it fails (exit 1): no order.
expect_exit(exec-copy-misses-order 1 "" "" check ${small} --expect-order 2 --integrator "${bad} copy {input} {output}")
# Bad input, before any level: an unclosed quote, an order or timeout out of range (exit 2).
expect_exit(exec-unclosed-quote 2 --integrator "unclosed single quote" converge ${small} --integrator "exec:prog 'a b\" c")
expect_exit(exec-bad-order 2 --exec-order -1 converge ${small} --exec-order -1)
expect_exit(exec-bad-timeout 2 --exec-timeout 0 converge ${small} --exec-timeout 0)
expect_exit(exec-not-in-precision 2 --integrator "exec:prog {input}" precision ${small} --integrator "exec:prog {input}")

# A program that never ends times out (exit 3, its last stderr line quoted); the timeout ends the
# program's whole process group, so does a SIGTERM to dlpverify (which then ends by it, as without
# a program), and the private folder of the exchange files is gone after a study, failed or not;
# `h5dump -H` of an exchange file shows every attribute; a reference program whose SPEC holds an '@'
# is run at the DT after the last '@'. The timeout and signal tests wait for the
# program to say it is ready, whatever the machine's speed (exec_contract.sh).
foreach(mode timeout timeout-group signal cleanup h5dump reference-at)
  add_test(NAME cli.exec-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/exec_contract.sh $<TARGET_FILE:dlpverify>
                                         ${CMAKE_CURRENT_SOURCE_DIR}/bad_integrator.py ${mode})
  set_tests_properties(cli.exec-${mode} PROPERTIES LABELS cli)
endforeach()
# A program named as the reference (--reference integrator:exec:COMMAND@DT) is run as --integrator's
# is: through the shell with --exec-shell (run as an argument list, this one would exit 0 and write
# nothing: "wrote no output file").
expect_exit(exec-reference-in-shell 3 "exited with status 5" "said in a shell" converge ${small} --exec-shell
            --reference "integrator:exec:echo said in a shell >&2 && exit 5@5e-4")
