# Tests that run once, in the plain build, and not again under the
# sanitizers: label "once", which .ci/run's ASan and UBSan pass leaves out
# (ctest -LE once). Each drives, over many cases, motions or levels, code
# that faster tests run under the sanitizers as well; what they add is
# their numbers, which the plain build proves. Times are of the ASan build
# at -j2 on two loaded cores, before the roof suite's tolerance went to
# 1e-9 (which made the ones that solve it slower still):
#   validation_integrators  409 s  every validation case with both
#                                  integrators (the solver: test_solve_*,
#                                  validation, validation_convergence)
#   verdict_default_model   260 s  a triaxial AC156 panel suite (the
#                                  synthetic path: test_synth)
#   fragility_anchorage     226 s  fragility searches over the concrete
#                                  check (fragility_cli, test_fragility)
#   spectrum_cli            221 s  spectra of AC156 suites (test_spectrum)
#   refactor_reports        212 s  check of every case in the tree; the
#                                  roof suite alone now passes its 60 s
#                                  cap under ASan (cases/: valgrind.sh)
#   synth_sets              122 s  matched sets over many seeds (test_synth)
#   units_us_outputs        115 s  every output of the US cases, AC156
#                                  suites among them (test_units)
# Together 1 565 s of the suite's 2 943 s of test time under ASan.
set(RB_ONCE_TESTS validation_integrators verdict_default_model fragility_anchorage
    spectrum_cli refactor_reports synth_sets units_us_outputs)
foreach(t ${RB_ONCE_TESTS})
  if(TEST ${t})
    set_property(TEST ${t} APPEND PROPERTY LABELS once)
  endif()
endforeach()
