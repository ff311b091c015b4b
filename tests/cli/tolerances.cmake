# Adaptive integrators verified by tolerance (--tolerances, docs/verification.md, "Adaptive
# integrators by tolerance"). tolerances.sh recomputes each exponent's fit and holds it to the
# exponent the error control predicts, E = q/(min(p, q) + 1) (tolerance_exponent.py says how, and
# within what).
set(tolerances_script ${CMAKE_CURRENT_SOURCE_DIR}/tolerances.sh)
function(expect_tolerances name code text)
  add_test(NAME cli.tolerances-${name} COMMAND bash ${tolerances_script} $<TARGET_FILE:dlpverify> ${code} ${text} ${ARGN})
  set_tests_properties(cli.tolerances-${name} PROPERTIES LABELS cli)
endfunction()

# CVODE Adams from rtol 1e-5 to 1e-10: its orders 5 … 7 on drag, 4 … 7 on full (last_order of the
# runs) predict 5/6 … 7/8 and 4/5 … 7/8; measured 0.964 ± 0.359 and 0.909 ± 0.163 on drag
# (position, velocity), 0.795–0.912 (half-widths 0.28–0.55) on full (CVODE reference at rtol
# 1e-12): the band meets every interval. The check itself: within 1 ± 0.25.
expect_tolerances(cvode-drag 0 "PASSED" check --integrator cvode --tolerances 1e-5:1e-10 --case drag --outer 4)
expect_tolerances(cvode-full 0 "PASSED" check --integrator cvode --tolerances 1e-5:1e-10 --case full --outer 4)
# ARKODE's Bogacki–Shampine 3(2) pair adapting its step: E = 3/(2 + 1) = 1; measured 0.966 and
# 0.969 over 5 runs, allowed ± 0.30 and ± 0.23 (half-widths 0.070, 0.055; pairwise exponents
# 0.81 … 1.04 and 0.85 … 1.02).
expect_tolerances(arkode-adaptive-drag 0 "PASSED" check --integrator arkode-adaptive:ARKODE_BOGACKI_SHAMPINE_4_2_3
                  --tolerances 1e-4:1e-8 --case drag --outer 4)
# ARKODE's implicit SDIRK 2(1) pair (ARKStep, Newton with matrix-free GMRES) adapting its step:
# E = 2/(1 + 1) = 1; measured 0.978 and 0.988 over rtol 1e-3 … 1e-6 (4 runs), allowed ± 0.054 and
# ± 0.024 (half-widths 0.022, 0.010; pairwise exponents 0.958 … 0.990 and 0.979 … 0.993, rising
# toward 1).
expect_tolerances(arkode-implicit-drag 0 "PASSED" check --integrator arkode-adaptive:ARKODE_SDIRK_2_1_2
                  --tolerances 1e-3:1e-6 --case drag --outer 4 --expect-proportionality 1)
set_tests_properties(cli.tolerances-arkode-implicit-drag PROPERTIES ENVIRONMENT "IMPLICIT=1")
# TR-BDF2 steps its order-2 solution and estimates with an order-3 embedding, so the estimate is
# the order-2 solution's own local error h^3 ≈ rtol and the global error h^2 ≈ rtol^(2/3)
# (docs/verification.md): E = 2/(2 + 1); measured 0.646 and 0.652 (half-widths 0.034, 0.010;
# pairwise exponents 0.57 … 0.70 and 0.63 … 0.67), allowed ± 0.168 and ± 0.051; the check's own
# ± 0.05 holds both by 2.5 x their distance from 2/3.
expect_tolerances(arkode-implicit-trbdf2 0 "PASSED" check --integrator arkode-adaptive:ARKODE_TRBDF2_3_3_2
                  --tolerances 1e-4:1e-8 --case drag --outer 4 --expect-proportionality 0.6667 --proportionality-tolerance 0.05)
set_tests_properties(cli.tolerances-arkode-implicit-trbdf2 PROPERTIES ENVIRONMENT "IMPLICIT=1")
# The Python example's midpoint rule takes "--rtol {rtol}" and ignores it: no error control, the
# same error at every tolerance (exponent 0 exactly), and the check says so.
expect_tolerances(exec-ignores-rtol 1 "the integrator ignores its tolerance"
                  check --case drag --outer 4 --tolerances 1e-3:1e-6
                  --integrator "exec:/usr/bin/python3 ${CMAKE_SOURCE_DIR}/examples/external/python/midpoint.py {input} {output} --rtol {rtol}")
set_tests_properties(cli.tolerances-exec-ignores-rtol PROPERTIES ENVIRONMENT "EXPONENT=0")

# Bad input names the option and the value.
expect_exit(bad-tolerances-range 2 --tolerances 1e-8:1e-4 check ${small} --integrator cvode --tolerances 1e-8:1e-4)
expect_exit(bad-tolerances-text 2 --tolerances abc check ${small} --integrator cvode --tolerances abc)
expect_exit(bad-tolerances-integrator 2 --integrator rk2 check ${small} --integrator rk2 --tolerances 1e-4:1e-8)
expect_exit(bad-tolerances-no-embedding 2 --integrator arkode-adaptive:ARKODE_KNOTH_WOLKE_3_3
            check ${small} --tolerances 1e-4:1e-8 --integrator arkode-adaptive:ARKODE_KNOTH_WOLKE_3_3)
expect_exit(bad-tolerances-unknown-table 2 --integrator arkode-adaptive:ARKODE_SDIRK_9_9_9
            check ${small} --tolerances 1e-4:1e-8 --integrator arkode-adaptive:ARKODE_SDIRK_9_9_9)
expect_exit(bad-tolerances-implicit-name-without-prefix 2 --integrator arkode-adaptive:SDIRK_2_1_2
            check ${small} --tolerances 1e-4:1e-8 --integrator arkode-adaptive:SDIRK_2_1_2)
expect_exit(bad-tolerances-exec-no-rtol 2 --integrator "" check ${small} --tolerances 1e-4:1e-8
            --integrator "exec:/usr/bin/python3 ${CMAKE_SOURCE_DIR}/examples/external/python/midpoint.py {input} {output}")

# The figure: error against rtol with the fitted exponents in the legend, and the RHS evaluations
# on the right axis of the same panel (one panel: one plot area, one y2 label).
add_test(NAME cli.tolerances-plot
         COMMAND bash -c "out=$(mktemp -d) && trap 'rm -rf $out' EXIT && $<TARGET_FILE:dlpverify> converge --integrator cvode --tolerances 1e-5:1e-8 --case drag --outer 4 --plot $out/t.svg >/dev/null && grep -q 'drag · cvode by tolerance' $out/t.svg && grep -q 'RHS evaluations per run' $out/t.svg && grep -q 'RHS evaluations (right axis)' $out/t.svg && grep -q 'position: E = ' $out/t.svg && [ $(grep -c 'relative L2 error' $out/t.svg) -eq 1 ]")
set_tests_properties(cli.tolerances-plot PROPERTIES LABELS cli)
