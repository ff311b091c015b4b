# Inputs are regular files of bounded size: FIFOs, devices, folders and oversized files named as
# any input are refused at once, exit 2, one line (inputs.sh).
add_test(NAME cli.inputs-regular-files
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/inputs.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR})
set_tests_properties(cli.inputs-regular-files PROPERTIES LABELS cli TIMEOUT 300)
# The property over every command that writes a file, the suite included: every output option
# pointed at an input, another output by another spelling, the run's own journal, a link to
# another study's journal, a dangling link, a FIFO, a device, a folder, a read-only folder or
# standard output with another output is refused before any work (exit 2 or 4), and every file
# is byte for byte what it was, nothing added.
add_test(NAME cli.paths-property
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/path_property.py $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR})
set_tests_properties(cli.paths-property PROPERTIES LABELS cli TIMEOUT 300)
# analyze blames a bad run (t_end = NaN, steps = -50, a column named twice) on its own file.
add_test(NAME cli.analyze-runs-checked
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/analyze_runs_checked.py $<TARGET_FILE:dlpverify>)
set_tests_properties(cli.analyze-runs-checked PROPERTIES LABELS cli TIMEOUT 60)
