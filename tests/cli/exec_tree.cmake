# A program dlpverify starts never outlives it, whatever it does: its children and grandchildren
# (even in a session of their own, or named with ')' and blanks) are ended on success, failure,
# timeout and SIGTERM; a FIFO at {output} is refused at once (exit 3), never read; the temporary
# folder is always removed; and {input}/{output} are quoted for the shell, so a TMPDIR with
# blanks, quotes or "t;touch X;" is only a name (exec_tree.sh, which writes its own small programs).
foreach(mode leave paren-name fail timeout signal signal-journal fifo fifo-hang quoting-space quoting-semicolon)
  add_test(NAME cli.exec-tree-${mode} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/exec_tree.sh $<TARGET_FILE:dlpverify> ${mode})
  set_tests_properties(cli.exec-tree-${mode} PROPERTIES LABELS cli)
endforeach()
