# A reason for every missed order (docs/verification.md, "Why an order was missed"), each provoked.
set(missed_script ${CMAKE_CURRENT_SOURCE_DIR}/missed_order.sh)
function(expect_reason name variable reason)
  add_test(NAME cli.missed-order-${name} COMMAND bash ${missed_script} $<TARGET_FILE:dlpverify> ${variable} ${reason} ${ARGN})
  set_tests_properties(cli.missed-order-${name} PROPERTIES LABELS cli)
endfunction()

# Euler on drag from Δt = 10 ms: ρ(J) ≈ 300/s (the drag rate), so Δt ρ ≈ 3 > 2, Euler's stability
# limit on the real axis: level 0's velocity error exceeds the solution.
expect_reason(stability velocity stability --case drag --outer 4 --integrator euler --expect-order 1
              --t-end 0.04 --dt 0.01 --levels 3 --no-escalate)
# Its finer levels fall faster than order 1 (2.17 position, 1.31 velocity, measured): no order below 1
# is seen, so the verdict is inconclusive (exit 5), the stability named as the reason.
set_tests_properties(cli.missed-order-stability PROPERTIES ENVIRONMENT EXPECT_EXIT=5)
# RK4 on drag from Δt = 7.8 µs: the errors sit within 1000 x of ε √n ‖y‖ / 2 (levels 6–7 of the
# round-off search of levels_auto.cmake), no level is asymptotic: double precision cannot decide
# (inconclusive, exit 5), and the reason says so.
expect_reason(round-off position round-off --case drag --outer 4 --integrator rk4 --expect-order 4
              --dt 7.8125e-06 --levels 3 --no-escalate)
set_tests_properties(cli.missed-order-round-off PROPERTIES ENVIRONMENT EXPECT_EXIT=5)
# By default the check settles it: stepped in double-double against the extended reference, the
# same levels and one more fit 4.001 and 4.000 (measured), and the report says what was escalated.
add_test(NAME cli.escalate-round-off
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 0 "so the study ran again in extended precision" --
                 $<TARGET_FILE:dlpverify> check --case drag --outer 4 --integrator rk4 --expect-order 4 --dt 7.8125e-06
                 --levels 3)
set_tests_properties(cli.escalate-round-off PROPERTIES LABELS cli)
# What cannot be stepped in extended precision is named: Crouzeix's SDIRK4 (a diagonally implicit
# file, solved by ARKStep in double) at the same steps stays inconclusive, the report saying why.
add_test(NAME cli.escalate-not-possible
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 5 "nothing the tool controls can go further: steps the explicit" --
                 $<TARGET_FILE:dlpverify> check --case drag --outer 4 --integrator tableau:${PROJECT_SOURCE_DIR}/examples/tableaux/sdirk4-crouzeix.toml
                 --expect-order 4 --dt 7.8125e-06 --levels 3)
set_tests_properties(cli.escalate-not-possible PROPERTIES LABELS cli)
# A CVODE reference at rtol 1e-4 is as wrong as RK2's levels (cli.untrustworthy-reference): no
# level measures the integrator, the verdict is inconclusive (exit 5), the reference named.
expect_reason(reference position reference-accuracy --case full --outer 4 --levels 3 --expect-order 2
              --reference-rtol 1e-4 --no-escalate)
set_tests_properties(cli.missed-order-reference PROPERTIES ENVIRONMENT EXPECT_EXIT=5)
# Over 0.4 s the rising particles of drag-gravity-vertical pass their apex (docs/model.md §4.4,
# at 0.37–0.39 s), where −K‖v‖v is only once differentiable: RK4's position misses order 4 over
# all five levels (4.23), and after the pre-asymptotic levels 0–1 its pairwise orders still move
# towards 4 (4.13 → 4.07, measured): inconclusive (exit 5), the kink named as the reason.
expect_reason(kink position kink --case drag-gravity-vertical --outer 4 --integrator rk4 --expect-order 4
              --t-end 0.4 --dt 0.002 --no-escalate)
set_tests_properties(cli.missed-order-kink PROPERTIES ENVIRONMENT EXPECT_EXIT=5)
# By default, with no level at a floor, the check searches finer levels in double by itself: nine
# levels, position passing at 3.908 over levels 5-7, velocity at 3.974 (measured).
add_test(NAME cli.escalate-finer-levels
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 0 "so a level search went on to finer levels in the same arithmetic, 9 levels" --
                 $<TARGET_FILE:dlpverify> check --case drag-gravity-vertical --outer 4 --integrator rk4 --expect-order 4
                 --t-end 0.4 --dt 0.002)
set_tests_properties(cli.escalate-finer-levels PROPERTIES LABELS cli)
