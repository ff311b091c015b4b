# Tests that check the values a command writes, not only that it ran. Each recomputes its numbers
# independently (closed forms, the lattice, hand formulas; see the script's header):
#   stagger      the contraction rows against dt/sqrt(ab) and the other spectral radii; Algorithm
#                7.1's counts (docs/cooling.md, Algorithm 7.1) as measured
#   precision    RK2's fitted order and rhs_evals = 2 steps; the Adams error falling with rtol
#   per-particle sqrt(sum err^2) over the rows = the finest level's L2; xi of the lattice
#   history      explicit Euler on gravity: L2 position = sqrt(N) g h t/2 at every row; RK2: rounding
#   cases        every documented case and every ARKODE explicit table of SUNDIALS 6.4, with orders
#   ratio3       a study at r = 3: pairwise and self-convergence orders, Richardson, GCI, the fit
foreach(check stagger precision per_particle history cases ratio3)
  string(REPLACE "_" "-" name ${check})
  add_test(NAME cli.values-${name}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/values_${check}.py $<TARGET_FILE:dlpverify>)
  set_tests_properties(cli.values-${name} PROPERTIES LABELS cli)
endforeach()
