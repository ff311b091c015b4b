# --levels auto (docs/verification.md, "Levels found by the study", the matrix): euler, rk2, heun
# and rk4 on drag, full, cooling and adiabat-ideal with levels the study found from the case's
# coarsest Δt (no --levels, default --order-ci), each with its exit code and why the search stopped (measured; the table in docs/verification.md). The first- and second-order
# methods narrow the interval long before their floor (10 to 28 levels finer); the search never
# goes on to the floor once the orders settle, so RK4 stops on drag at its narrow interval; on
# adiabat-ideal the floor comes first (round-off); on full (below) the tightest CVODE reference
# stops it first, and cooling passes by the order extrapolated from the differences between
# successive levels (below). Small populations keep the suite quick. Every search here but the
# budget's own test runs at --budget 1e7 (the most), so no verdict depends on wall time; every one
# is checked by levels_auto.sh against the status and trust rules recomputed from its JSON, and
# every order it extrapolates against Aitken's Δ² recomputed from its pairwise orders.
set(auto_budget --budget 1e7)
set(auto_script ${CMAKE_CURRENT_SOURCE_DIR}/levels_auto.sh)
set(auto_drag --case drag --outer 4)
set(auto_full --case full --outer 4)
set(auto_cooling --case cooling --particles 20)
set(auto_adiabat --case adiabat-ideal --parcels 8)
foreach(run
        euler:1:drag:order-interval euler:1:full:order-interval euler:1:cooling:order-interval
        euler:1:adiabat:order-interval
        rk2:2:drag:order-interval rk2:2:full:order-interval rk2:2:cooling:order-interval rk2:2:adiabat:order-interval
        heun:2:drag:order-interval heun:2:full:order-interval heun:2:cooling:order-interval
        heun:2:adiabat:order-interval
        rk4:4:drag:order-interval rk4:4:adiabat:round-off)
  string(REPLACE ":" ";" fields ${run})
  list(GET fields 0 integrator)
  list(GET fields 1 order)
  list(GET fields 2 case)
  list(GET fields 3 stop)
  add_test(NAME cli.levels-auto-${case}-${integrator}
           COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 ${stop} ${auto_${case}} --integrator ${integrator}
                   --expect-order ${order} ${auto_budget})
  set_tests_properties(cli.levels-auto-${case}-${integrator} PROPERTIES LABELS cli)
endforeach()

# RK4's error on `full` comes within 100 x of the CVODE reference's at the default rtol 1e-12 by
# the third level (velocity margin 34.1, measured), before the interval narrows: the search
# tightens the reference once, to rtol 1e-14, and solves its levels again. Four levels are
# trusted (level 4's velocity error is only 25.4 x the tightest reference's: left out); velocity
# and mass narrow over all four, but position and temperature leave level 0 as pre-asymptotic
# (order 4.09 to level 1, 0.06 from the finer levels' 4.03, measured), and three levels do not
# narrow (half-widths 0.083 and 0.088): their pairwise orders over the four trusted levels (4.095,
# 4.048, 4.023 for temperature) extrapolate to 3.998 ± 0.024 and 3.999 ± 0.025 and the check
# passes by them. The counts hold by a factor 4 either way (level 3's velocity margin 425, level
# 4's 25.4, against 100; level_search_rules.py asserts the rule itself).
add_test(NAME cli.levels-auto-full-rk4
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 reference-accuracy ${auto_full} --integrator rk4
                 --expect-order 4 ${auto_budget})
set_tests_properties(cli.levels-auto-full-rk4 PROPERTIES LABELS cli ENVIRONMENT
                     "EXPECT_TIGHTENINGS=1;EXPECT_TIGHTENED_TO=rtol 1e-14;EXPECT_KEPT=4;EXPECT_EXTRAPOLATED=temperature;EXPECT_SOURCE=reference errors")
# On `cooling` RK4 is still pre-asymptotic (pairwise orders 4.34, 4.18, 4.09 from the case's 10 ms)
# where its error meets the CVODE reference's even at its floor rtol 1e-14 (margin 14.4 at 1.25 ms,
# measured): the search tightens the reference once (1e-12 -> 1e-14, level 1's margin 90.7),
# stops on the reference's accuracy and says the reference can be made no tighter. The three
# trusted levels give two pairwise orders, one short of an extrapolated order (docs/verification.md,
# "An order extrapolated from the pairwise orders"), so the search refines on three levels beyond
# the reference's trust (to 0.3125 ms), outside the fit, for the differences between successive
# levels: their pairwise orders 4.354, 4.190, 4.098, 4.047 (gap ratios 0.57, 0.54, measured)
# extrapolate to 3.988 ± 0.071, and the check passes by it (|3.988 − 4| ≤ 0.1, and 4 within the
# half-width). The fit keeps the 3 trusted levels (level 2's margin 233, level 3's 14.4, against
# 100). The extrapolate is asserted as Aitken's Δ² of the pairwise orders, recomputed.
add_test(NAME cli.levels-auto-cooling-rk4-reference
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 reference-accuracy ${auto_cooling} --integrator rk4
                 --expect-order 4 ${auto_budget})
set_tests_properties(cli.levels-auto-cooling-rk4-reference PROPERTIES LABELS cli ENVIRONMENT
                     "EXPECT_TIGHTENINGS=1;EXPECT_TIGHTENED_TO=rtol 1e-14;EXPECT_KEPT=3;EXPECT_BEYOND=3;EXPECT_EXTRAPOLATED=temperature;EXPECT_SOURCE=self-differences")
# At the floor already, the reference is not tightened; the same levels and extrapolate.
add_test(NAME cli.levels-auto-cooling-rk4-floor
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 reference-accuracy ${auto_cooling} --integrator rk4
                 --expect-order 4 --reference-rtol 1e-14 ${auto_budget})
set_tests_properties(cli.levels-auto-cooling-rk4-floor PROPERTIES LABELS cli ENVIRONMENT
                     "EXPECT_TIGHTENINGS=0;EXPECT_KEPT=3;EXPECT_BEYOND=3;EXPECT_EXTRAPOLATED=temperature;EXPECT_SOURCE=self-differences")
# From 20 ms the same search keeps four trusted levels (20 … 2.5 ms) and three pairwise orders
# 4.583, 4.344, 4.180 (gap ratio 0.69, measured): the order is extrapolated, 3.813 ± 0.366
# (Aitken; the half-width is the whole last step). 3.813 is outside 4 ± 0.1, but 4 lies within
# the extrapolate's half-width: further from the asymptotic range the Δt⁶ … terms bend the gaps,
# the data cannot decide, and the check says inconclusive (exit 5) rather than failing a correct
# method.
add_test(NAME cli.levels-auto-cooling-rk4-extrapolated
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 5 reference-accuracy ${auto_cooling} --integrator rk4
                 --expect-order 4 --dt 0.02 ${auto_budget})
set_tests_properties(cli.levels-auto-cooling-rk4-extrapolated PROPERTIES LABELS cli ENVIRONMENT
                     "EXPECT_KEPT=4;EXPECT_EXTRAPOLATED=temperature;EXPECT_SOURCE=reference errors")

# An integrator reference is tightened by the ratio: rk2 against rk2 at 0.5 ms gains only 4 x a
# time, so the search tightens it 4 times (to 31.25 us, the most a search does; margins 0, 3.15,
# 16, 67.8 on level 0, measured) and stops on the reference's accuracy, saying so. Its three
# trusted levels' pairwise orders still move towards 2 (position 2.53 -> 2.21, velocity 2.26 ->
# 2.13, measured): inconclusive, exit 5.
add_test(NAME cli.levels-auto-integrator-reference
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 5 reference-accuracy ${auto_drag} --integrator rk2
                 --expect-order 2 --reference integrator:rk2@5e-4 ${auto_budget})
set_tests_properties(cli.levels-auto-integrator-reference PROPERTIES LABELS cli
                     ENVIRONMENT "EXPECT_TIGHTENINGS=4;EXPECT_TIGHTENED_TO=rk2 at dt = 3.125e-05")

# RK4 on drag converges at order 4 from the case's 0.5 ms down to the round-off floor (level 7,
# 3.9e-14 <= its floor 4.4e-14, measured). At the default ±0.05 the intervals are narrow at
# level 3 and confirmed at level 4, with the floor still 4 levels finer: the search stops there,
# on levels a verdict can rest on, and does not refine on to the floor. At ±0.01 the floor comes
# before the interval narrows; level_search_rules.py asserts the status rules (the finest level
# at round-off, every coarser one in the asymptotic range, recomputed from the errors and floors).
add_test(NAME cli.levels-auto-rk4-drag-round-off
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 order-interval ${auto_drag} --integrator rk4 --expect-order 4
                 ${auto_budget})
set_tests_properties(cli.levels-auto-rk4-drag-round-off PROPERTIES LABELS cli
                     ENVIRONMENT "EXPECT_REASON=95% interval is within")
add_test(NAME cli.levels-auto-rk4-drag-round-off-narrow
         COMMAND bash ${auto_script} $<TARGET_FILE:dlpverify> 0 round-off ${auto_drag} --integrator rk4 --expect-order 4
                 --order-ci 0.01 ${auto_budget})
set_tests_properties(cli.levels-auto-rk4-drag-round-off-narrow PROPERTIES LABELS cli
                     ENVIRONMENT "EXPECT_REASON=before the order interval narrowed")

# A start at the round-off floor is coarsened: rk4 on drag from Δt = 0.5 ms / 2^9. `converge`
# (exit 0 once the study is done) rather than `check`, whose verdict on the three levels above
# the floor it ends at hangs on a level within 2.1 x of its floor; the exit status is kept.
add_test(NAME cli.levels-auto-coarsens
         COMMAND bash -c "table=$($<TARGET_FILE:dlpverify> converge --levels auto --case drag --outer 4 --integrator rk4 --dt 9.765625e-07 --budget 1e7) && grep -q 'set aside: the start is at the round-off floor' <<<\"$table\"")
set_tests_properties(cli.levels-auto-coarsens PROPERTIES LABELS cli)

# Bad input names the option and the value.
expect_exit(bad-levels-word 2 --levels many converge ${small} --levels many)
expect_exit(bad-budget 2 --budget 0 converge ${small} --levels auto --budget 0)
expect_exit(bad-order-ci 2 --order-ci -0.1 converge ${small} --levels auto --order-ci -0.1)
expect_exit(bad-levels-auto-precision 2 --levels auto precision ${small} --levels auto)
expect_exit(bad-levels-auto-resume 2 --resume "" converge ${small} --levels auto --resume)

# A budget that binds on any machine (1e-300 s: after the two levels a search always runs) leaves
# one pairwise order and no interval: no order measured, exit 1, the stop named.
add_test(NAME cli.levels-auto-budget-binds
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 1 "FAIL, no order measured: the search stopped (budget)" --
                 $<TARGET_FILE:dlpverify> check --levels auto --budget 1e-300 --case drag --outer 4 --integrator rk2
                 --expect-order 2)
set_tests_properties(cli.levels-auto-budget-binds PROPERTIES LABELS cli)
