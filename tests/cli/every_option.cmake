# Every option that validates its value has a bad-input test of its own (issue 9): exit 2, one
# line on stderr naming the option and the value, no output. Included from CMakeLists.txt, where
# expect_exit() and ${small} are defined. The inventory, from src/case_study/options.cpp, setup.cpp,
# precision.cpp, src/cli/study_file.cpp and plot_command.cpp — (*) marks a test in CMakeLists.txt:
#   cloud       --shape (*) --outer (*, and > 2000 here) --inner (*, and < 0 here) --spacing (*) --us
#   physics     --diameter (*) --rho-p (*) --rho-gas (*) --cs --t-particle --mu-gas --cp-gas
#               --prandtl --t-gas --cd --g --cb
#   case        --case unknown (*), past burn-out (*), a closed form that fails its audit
#   levels      --t-end (*) --dt (*) --levels (*, and > 30 here) --ratio (*) --threads
#   reference   --reference (*, and an unknown kind here) --reference-rtol
#   CVODE       --rtol (*) --atol --method (*) --linear-solver --max-steps --vector
#   outputs     two outputs on one path, an output on the study file; --history-outputs
#   check       --expect-order (*, and missing, NAME=P of no variable and =P here) --order-tolerance
#   precision   --rtol-min (*) --per-decade (*) --integrator cvode (*) --rtol-max, --rtol-min above
#               --rtol-max, --per-decade > 20, --reference-rtol too loose for the sweep
#   study file  missing (*), unknown key (*), given twice, a section, naming another, a key with
#               two values, no file name, a bad value (named by its option); not TOML, a key
#               of the wrong type, an empty value, an option that does nothing: study_toml.cmake
#   integrator  unknown (*), unknown ARKODE table (*), not a number (*, --dt abc), unknown option (*)
#   plot        a bad figure extension and mixed inputs (plot_contract.sh refusals); a missing
#               input and a JSON that is not a result, here
#   gas cases   --p-ref --t-ref --molar-mass --rho0 (and with --molar-mass) --gamma (one, text)
#               --vdw-b --parcels (0) --period --j-min-low (and above high) --t-spread, a path
#               through b', --vdw-a on the ideal gas, options of the other problem, the gas
#               update on the DLP, --per-particle on a gas case (*); --j-min-high, --vdw-a < 0,
#               --parcels > 1e7 and --vdw-b on the ideal gas here
#   baseline    --baseline (not JSON, missing, another study, another order) --constant-tolerance
#               (out of (0, 1), without --baseline), --json onto the baseline: constant.sh
#   compare     --order-tolerance --constant-tolerance, a missing input, --json onto an input: constant.sh
#   sharpness   --delta --order-tolerance --constant-tolerance --alternative-reference, an integrator
#               that is not tableau:FILE: constant.sh
set(fixtures ${CMAKE_CURRENT_SOURCE_DIR})

expect_exit(bad-outer-too-large 2 --outer 2001 converge --outer 2001)
expect_exit(bad-inner-negative 2 --inner -1 converge ${small} --inner -1)
expect_exit(bad-us 2 --us 0 converge ${small} --us 0)
expect_exit(bad-cs 2 --cs 0 converge ${small} --cs 0)
expect_exit(bad-t-particle 2 --t-particle -5 converge ${small} --t-particle -5)
expect_exit(bad-mu-gas 2 --mu-gas 0 converge ${small} --mu-gas 0)
expect_exit(bad-cp-gas 2 --cp-gas 0 converge ${small} --cp-gas 0)
expect_exit(bad-prandtl 2 --prandtl 0 converge ${small} --prandtl 0)
expect_exit(bad-t-gas 2 --t-gas 0 converge ${small} --t-gas 0)
expect_exit(bad-cd 2 --cd 0 converge ${small} --cd 0)
expect_exit(bad-cd-negative 2 --cd -0.5 converge ${small} --cd -0.5)
expect_exit(bad-g 2 --g -9.81 converge ${small} --g -9.81)
expect_exit(bad-cb 2 --cb -1 converge ${small} --cb -1)
# ρ_p = 1e-6 kg/m³ makes drag so fast (K ≈ 4e9 1/m) that CVODE at rtol 1e-12 and the closed form
# part by 1e-4: the audit refuses the closed form as a reference, naming the case.
expect_exit(bad-case-closed-form-fails-audit 2 --case drag converge ${small} --case drag --levels 2 --rho-p 1e-6)

expect_exit(bad-levels-too-many 2 --levels 31 converge ${small} --levels 31)
expect_exit(bad-threads 2 --threads -1 converge ${small} --threads -1)
expect_exit(bad-reference-kind 2 --reference fuzzy converge ${small} --reference fuzzy)
expect_exit(bad-reference-rtol 2 --reference-rtol 0.001 converge ${small} --reference-rtol 1e-3)
expect_exit(bad-reference-rtol-tiny 2 --reference-rtol 1e-15 converge ${small} --reference-rtol 1e-15)
expect_exit(bad-atol 2 --atol 0 converge ${small} --integrator cvode --atol 0)
expect_exit(bad-linear-solver 2 --linear-solver lu converge ${small} --integrator cvode --method bdf --linear-solver lu)
expect_exit(bad-max-steps 2 --max-steps 0 converge ${small} --max-steps 0)
expect_exit(bad-vector 2 --vector cuda converge ${small} --vector cuda)
expect_exit(bad-history-outputs 2 --history-outputs 0 converge ${small} --history-outputs 0)
expect_exit(bad-history-outputs-too-many 2 --history-outputs 100001 converge ${small} --history-outputs 100001)
expect_exit(bad-output-twice 2 --history same.csv converge ${small} --per-particle same.csv --history same.csv)

expect_exit(bad-expect-order-missing 2 --expect-order "" check ${small})
expect_exit(bad-expect-order-variable 2 --expect-order energy=3 check ${small} --expect-order 2 --expect-order energy=3)
expect_exit(bad-expect-order-form 2 --expect-order =3 check ${small} --expect-order 2 --expect-order =3)
expect_exit(bad-order-tolerance 2 --order-tolerance 0 check ${small} --expect-order 2 --order-tolerance 0)

expect_exit(precision-bad-rtol-max 2 --rtol-max 1 precision ${small} --rtol-max 1)
expect_exit(precision-bad-rtol-min-above-max 2 --rtol-min 1e-06 precision ${small} --rtol-max 1e-8 --rtol-min 1e-6)
expect_exit(precision-bad-per-decade-too-many 2 --per-decade 21 precision ${small} --per-decade 21)
expect_exit(precision-bad-reference-rtol 2 --reference-rtol 1e-12 precision ${small} --reference cvode --reference-rtol 1e-12)

expect_exit(bad-study-file-twice 2 --config ${fixtures}/override.toml
            converge --config ${fixtures}/override.toml --config ${fixtures}/override.toml)
expect_exit(bad-study-file-section 2 --config ${fixtures}/section.toml converge --config ${fixtures}/section.toml)
expect_exit(bad-study-file-nested 2 --config ${fixtures}/nested-config.toml converge --config ${fixtures}/nested-config.toml)
expect_exit(bad-study-file-two-values 2 --config ${fixtures}/array-value.toml converge --config ${fixtures}/array-value.toml)
expect_exit(bad-study-file-value 2 --cd 0 converge --config ${fixtures}/bad-cd.toml)

# --config as the last word, with no file name (exit 2 naming --config; no outputs appended here).
add_test(NAME cli.bad-study-file-no-name
         COMMAND bash -c "err=\$($<TARGET_FILE:dlpverify> converge --outer 4 --config 2>&1 >/dev/null); test \$? -eq 2 && test \"\$err\" = 'dlpverify: --config: needs a file name'")
set_tests_properties(cli.bad-study-file-no-name PROPERTIES LABELS cli)

# An output on the study file itself is refused, and the study file is left as it was.
add_test(NAME cli.bad-output-over-study-file
         COMMAND bash -c "set -u; d=$(mktemp -d); trap 'rm -rf $d' EXIT; cp ${fixtures}/override.toml $d/s.toml; $<TARGET_FILE:dlpverify> converge --config $d/s.toml --per-particle $d/s.toml 2>$d/err >/dev/null; c=$?; test $c -eq 2 && test $(wc -l <$d/err) -eq 1 && grep -q -- '--per-particle' $d/err && cmp -s ${fixtures}/override.toml $d/s.toml")
set_tests_properties(cli.bad-output-over-study-file PROPERTIES LABELS cli)

# plot: an input that does not exist, and a JSON that is not a result: exit 2, one line naming
# the input, no figure.
add_test(NAME cli.bad-plot-input-missing
         COMMAND bash -c "set -u; d=$(mktemp -d); trap 'rm -rf $d' EXIT; $<TARGET_FILE:dlpverify> plot $d/missing.json -o $d/f.png 2>$d/err >/dev/null; c=$?; test $c -eq 2 && test $(wc -l <$d/err) -eq 1 && grep -q 'missing.json' $d/err && test ! -e $d/f.png")
set_tests_properties(cli.bad-plot-input-missing PROPERTIES LABELS cli)
add_test(NAME cli.bad-plot-input-not-a-result
         COMMAND bash -c "set -u; d=$(mktemp -d); trap 'rm -rf $d' EXIT; echo '{\"a\": 1}' >$d/other.json; $<TARGET_FILE:dlpverify> plot $d/other.json -o $d/f.png 2>$d/err >/dev/null; c=$?; test $c -eq 2 && test $(wc -l <$d/err) -eq 1 && grep -q 'other.json' $d/err && test ! -e $d/f.png")
set_tests_properties(cli.bad-plot-input-not-a-result PROPERTIES LABELS cli)

set(gas_case --case adiabat-vdw --parcels 8)
expect_exit(gas-bad-j-min-high 2 --j-min-high 1.5 converge ${gas_case} --j-min-high 1.5)
expect_exit(gas-bad-vdw-a 2 --vdw-a -1 converge ${gas_case} --vdw-a -1)
expect_exit(gas-parcels-too-many 2 --parcels 10000001 converge ${gas_case} --parcels 10000001)
expect_exit(gas-vdw-b-on-ideal 2 --vdw-b 0.0001 converge --case adiabat-ideal --parcels 8 --vdw-b 1e-4)
