# The progress line of long work: shown under a pseudo-terminal (util-linux `script`), absent in a
# pipe and with --quiet, never in standard output or a result file (progress.sh).
foreach(mode study precision compress)
  add_test(NAME cli.progress-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/progress.sh $<TARGET_FILE:dlpverify> ${mode})
  set_tests_properties(cli.progress-${mode} PROPERTIES LABELS cli)
endforeach()
