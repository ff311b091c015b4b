# docs/cli.md against the program's --help: every command has its section, every option of a
# command's --help is in that section with its default (and the section lists no other), and the
# usage lines name the program (Usage: dlpverify [OPTIONS] SUBCOMMAND).
add_test(NAME docs.help-vs-cli
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/docs/help_vs_cli.py $<TARGET_FILE:dlpverify>
                 ${CMAKE_SOURCE_DIR}/docs/cli.md)
set_tests_properties(docs.help-vs-cli PROPERTIES LABELS cli)
