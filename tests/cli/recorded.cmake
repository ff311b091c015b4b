# An independent implementation of docs/model.md (numpy, tests/independent_dlp.py) recomputes every
# level's L2 norms of a study and agrees to 1e-6 relative (closed forms), or within that plus the two
# references' estimated errors (its own Richardson-extrapolated RK4 against dlpverify's CVODE), per
# case: each DLP term (drag, C_D(Re), gravity, heat, burning) against code that shares none.
set(_independent_studies
    "drag rk2 --outer 6 --levels 4"
    "drag euler --outer 6 --levels 4"
    "drag heun --outer 6 --levels 4"
    "drag rk4 --outer 6 --levels 4"
    "gravity euler --outer 4 --levels 3"
    "gravity rk2 --outer 4 --levels 3"
    # u_s 6 m/s puts the z axis's particles on both sides of v_t: rising, through an apex, falling
    # slower and faster than v_t
    "drag-gravity-vertical rk2 --outer 6 --us 6 --levels 3"
    "drag-gravity-vertical rk4 --outer 6 --us 6 --levels 3 --dt 0.01"
    "drag-gravity rk2 --outer 4 --levels 3"
    "drag-gravity rk4 --outer 4 --levels 3 --dt 0.001 --reference-rtol 1e-14"
    "drag-heat rk2 --outer 4 --levels 3"
    "drag-heat rk4 --outer 4 --levels 3"
    "burn rk2 --outer 4 --levels 3"
    "burn rk4 --outer 4 --levels 3"
    "drag-law rk2 --outer 4 --levels 3"
    "drag-law rk4 --outer 4 --levels 3 --dt 0.001 --reference-rtol 1e-14"
    "full rk2 --outer 4 --levels 3")
foreach(study IN LISTS _independent_studies)
  separate_arguments(arguments UNIX_COMMAND "${study}")
  list(POP_FRONT arguments case integrator)
  list(JOIN arguments " " options)
  add_test(NAME cli.independent-norms-${case}-${integrator}
           COMMAND bash -c "set -e; d=$(mktemp -d); trap 'rm -rf $d' EXIT; $<TARGET_FILE:dlpverify> converge --case ${case} --integrator ${integrator} ${options} --json $d/s.json > /dev/null; /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/independent_dlp.py $d/s.json")
  set_tests_properties(cli.independent-norms-${case}-${integrator} PROPERTIES LABELS cli)
endforeach()

# The L2 norms of three studies recorded with their build's provenance (drag RK2, `full` with the
# CVODE reference, an ARKODE table), each reproduced within its own tolerance at every level.
add_test(NAME cli.recorded-l2-norms
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/recorded/compare_norms.py
                 $<TARGET_FILE:dlpverify> ${CMAKE_SOURCE_DIR}/tests/recorded/l2-norms.json)
set_tests_properties(cli.recorded-l2-norms PROPERTIES LABELS cli)
