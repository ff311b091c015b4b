# One run's outputs are written together or not at all: a file-size limit that fails the largest
# output leaves every old output of converge, precision, stagger, compress, plot and audit as it
# was (exit 4, one line naming the output), and --resume then finishes a journaled study.
foreach(mode converge precision stagger compress plot audit)
  add_test(NAME cli.output-set-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/output_set.sh $<TARGET_FILE:dlpverify> ${mode})
  set_tests_properties(cli.output-set-${mode} PROPERTIES LABELS cli)
endforeach()
