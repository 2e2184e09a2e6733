# rockbolt fragility end to end (docs/fragility.md).
rb_script_test(NAME fragility_cli SCRIPT tests/fragility/fragility.py LABEL fragility)
# batch --fragility against fragility, row by row, and its determinism
rb_script_test(NAME fragility_batch_property SCRIPT tests/fragility/batch_property.py
               LABEL fragility)
# --sweep-gap: each point the fragility of the case with that gap ratio;
# the figure; bad ranges refused
rb_script_test(NAME fragility_sweep_gap SCRIPT tests/fragility/sweep.py LABEL fragility)
# --p58: the FEMA P-58 rows, read back with Python's csv module
rb_script_test(NAME fragility_p58 SCRIPT tests/fragility/p58.py LABEL fragility)
# the anchorage limit state over random cases with concrete: each motion's
# capacity is the level at which design finds its anchorage failing; the
# governing state, the P-58 row, batch and merge; none without concrete
rb_script_test(NAME fragility_anchorage SCRIPT tests/fragility/anchorage.py LABEL fragility
               TIMEOUT 900)
# the lift-off capacity over random cabinets: the first failing level to
# the search's resolution, by a brute-force scan down to the floor
rb_script_test(NAME fragility_lift_off SCRIPT tests/fragility/lift_off.py LABEL fragility)
# the searches with fewer runs: usage and first-yield capacities against
# design's factors to the resolution, the governing state confirmed,
# check at each capacity, one thread and two
rb_script_test(NAME fragility_fewer_runs SCRIPT tests/fragility/fewer_runs.py LABEL fragility)
# capacities the model limits (the vertical reaching -g), by hand, marked
# in JSON, text and figure, counted as reached; the confirmed states named
rb_script_test(NAME fragility_model_limit SCRIPT tests/fragility/model_limit.py
               LABEL fragility)
