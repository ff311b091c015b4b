# --reference integrator:SPEC@DT (docs/verification.md, "The reference"): on `full`, an rk4
# reference at Δt = 1e-5 s gives the observed orders of the CVODE reference to the three decimals
# the table prints; an rk2 reference at twice the finest level's step is refused by the trust
# margin (exit 1, as an untrusted CVODE reference); a malformed spec is bad input (exit 2, one
# line naming --reference and the value, no file written).
add_test(NAME cli.reference-integrator-orders
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/reference_orders.sh $<TARGET_FILE:dlpverify>)
set_tests_properties(cli.reference-integrator-orders PROPERTIES LABELS cli)

# The finest level of full's defaults is 0.5 ms / 2^4 = 3.125e-5 s; rk2 at 6.25e-5 s is as wrong
# as the levels it would measure: with e = C dt^2 the margin is 0.75 ((1 - 1/4) e / ((4/3)(1 - 1/4) e)).
# Every level measures the reference: the check cannot decide (exit 5).
# (The single pass: escalated, the study runs against the extended reference instead.)
expect_exit(reference-integrator-too-coarse 5 "" "" check --case full ${small} --expect-order 2
            --reference integrator:rk2@6.25e-5 --no-escalate)
add_test(NAME cli.reference-integrator-too-coarse-says-why
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/expect_output.sh 5 "the reference cannot decide here" --
                 $<TARGET_FILE:dlpverify> check --case full --outer 4 --expect-order 2 --reference integrator:rk2@6.25e-5
                 --no-escalate)
set_tests_properties(cli.reference-integrator-too-coarse-says-why PROPERTIES LABELS cli)

expect_exit(bad-reference-integrator-name 2 --reference integrator:nope@1e-3
            converge ${small} --case full --reference integrator:nope@1e-3)
expect_exit(bad-reference-integrator-no-step 2 --reference integrator:rk4
            converge ${small} --case full --reference integrator:rk4)
expect_exit(bad-reference-integrator-step-text 2 --reference integrator:rk4@abc
            converge ${small} --case full --reference integrator:rk4@abc)
expect_exit(bad-reference-integrator-step-not-whole 2 --reference integrator:rk4@0.3
            converge ${small} --case full --reference integrator:rk4@0.3)
expect_exit(bad-reference-integrator-step-zero 2 --reference integrator:rk4@0
            converge ${small} --case full --reference integrator:rk4@0)
expect_exit(bad-reference-integrator-precision 2 --reference integrator:rk4@0.3
            precision ${small} --case full --reference integrator:rk4@0.3)
