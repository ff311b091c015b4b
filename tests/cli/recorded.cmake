# An independent implementation of docs/model.md (numpy) reproduces the L2 norms to 1e-6 at every level.
foreach(integrator rk2 euler heun rk4)
  add_test(NAME cli.independent-norms-${integrator}
           COMMAND bash -c "set -e; d=$(mktemp -d); trap 'rm -rf $d' EXIT; $<TARGET_FILE:dlpverify> converge --case drag --integrator ${integrator} --outer 6 --levels 4 --json $d/s.json > /dev/null; /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/independent_drag.py $d/s.json")
  set_tests_properties(cli.independent-norms-${integrator} PROPERTIES LABELS cli)
endforeach()

# L2 norms recorded before the harness became problem-independent: drag with RK2, full with the
# CVODE reference, and one ARKODE table, each reproduced to 1e-12 relative at every level.
add_test(NAME cli.recorded-l2-norms
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/recorded/compare_norms.py
                 $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR}/tests/recorded/l2-norms.json)
set_tests_properties(cli.recorded-l2-norms PROPERTIES LABELS cli)
