# The thermal cases and the staggering command (docs/model.md §7.3). Included from CMakeLists.txt,
# where expect_exit() is defined.
set(cool --case cooling --particles 20)

# Bad input: exit 2, one line naming the option and the value, no output.
expect_exit(cooling-bad-particles 2 --particles 0 converge ${cool} --particles 0)
expect_exit(cooling-bad-h-c 2 --h-c -1 converge ${cool} --h-c -1)
expect_exit(cooling-bad-theta-gas 2 --theta-gas -300 converge ${cool} --theta-gas -300)
expect_exit(cooling-bad-theta-surroundings 2 --theta-surroundings nan converge ${cool} --theta-surroundings nan)
expect_exit(cooling-bad-density 2 --particle-density 0 converge ${cool} --particle-density 0)
expect_exit(cooling-bad-heat-capacity 2 --heat-capacity -900 converge ${cool} --heat-capacity -900)
expect_exit(cooling-bad-d-min 2 --d-min 0 converge ${cool} --d-min 0)
expect_exit(cooling-bad-d-order 2 --d-min 0.001 converge ${cool} --d-min 1e-3)
expect_exit(cooling-bad-emissivity 2 --emissivity-max 1.5 converge ${cool} --emissivity-max 1.5)
expect_exit(cooling-bad-theta0 2 --theta0-min 2000 converge ${cool} --theta0-min 2000)
expect_exit(stagger-bad-a 2 --a 0 converge --case stagger-2x2 --a 0)
expect_exit(stagger-bad-systems 2 --systems 0 converge --case stagger-2x2 --systems 0)
expect_exit(cooling-dlp-option 2 --outer "" converge ${cool} --outer 7)
expect_exit(dlp-cooling-option 2 --h-c "" converge --case drag --outer 3 --h-c 7)
expect_exit(cooling-exact-with-convection 2 --reference exact converge ${cool} --reference exact)
expect_exit(stagger-bad-dt 2 --dt -1 stagger --dt -1)
expect_exit(stagger-bad-sweep 2 --sweep sor stagger --dt 0.5 --sweep sor)
expect_exit(stagger-bad-tol 2 --tol 0 stagger --adaptive --dt 1.5 --tol 0)
expect_exit(stagger-bad-block-tol 2 --block-tol w9=1e-6 stagger --adaptive --dt 1.5 --block-tol w9=1e-6)
expect_exit(stagger-bad-target-sweeps 2 --target-sweeps 1 stagger --adaptive --dt 1.5 --target-sweeps 1)
expect_exit(stagger-adaptive-two-steps 2 --dt 0.5 stagger --adaptive --dt 1.5,0.5)

# Verdicts: implicit-fp is order 1 (a claim of 2 fails), a diverging fixed point is a solver
# failure (exit 3, no output), a step above the coupling's limit diverges (exit 3).
expect_exit(implicit-fp-misses-order-2 1 "" "" check ${cool} --integrator implicit-fp --expect-order 2)
expect_exit(implicit-fp-diverges 3 "" "" converge --case cooling-radiation-vacuum --particles 4 --integrator implicit-fp
            --t-end 2 --dt 1 --levels 2 --theta0-min 3000 --theta0-max 3000)
expect_exit(stagger-above-limit-diverges 3 "" "" stagger --case stagger-2x2 --dt 0.5,1.2)
expect_exit(stagger-3x3-above-limit-diverges 3 "" "" stagger --case stagger-3x3 --dt 1.1 --sweep gauss-seidel)
# The contraction rows and both adaptive modes' counts: cli.values-stagger (values.cmake).
# A block whose own backward-Euler solve cannot settle (cooling at dt 0.1: dt |df/dT| > 1) fails
# the step with exit 3 naming the block and the cure, not a "measured contraction nan".
add_test(NAME cli.stagger-block-solve-fails
         COMMAND bash -c "out=$(\"$0\" stagger --case cooling --dt 0.1 2>&1); [ $? -eq 3 ] && grep -q 'at --dt 0.1 the backward-Euler solve of block T does not settle in sweep 1: its fixed-point iteration converges only while dt |df/dy| < 1, so take a smaller step' <<<\"$out\" && ! grep -q nan <<<\"$out\""
                 $<TARGET_FILE:dlpverify>)
set_tests_properties(cli.stagger-block-solve-fails PROPERTIES LABELS cli)
