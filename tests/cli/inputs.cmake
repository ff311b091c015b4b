# Inputs are regular files of bounded size: FIFOs, devices, folders and oversized files named as
# any input are refused at once, exit 2, one line (inputs.sh).
add_test(NAME cli.inputs-regular-files
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/inputs.sh $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR})
set_tests_properties(cli.inputs-regular-files PROPERTIES LABELS cli TIMEOUT 300)
