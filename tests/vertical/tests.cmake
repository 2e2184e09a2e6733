# The floor's vertical acceleration end to end: a rigid block under a
# harmonic horizontal and vertical against an integration written in the
# test (docs/solver.md, "Vertical floor acceleration").
rb_script_test(NAME vertical_block SCRIPT tests/vertical/vertical.py LABEL vertical)
