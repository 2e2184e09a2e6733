# rockbolt motion end to end: its AT2 and CSV files hold the floor the
# solver sees (an independent building filter), and read back as records
# they give the case's own results (docs/motion.md, "Motions for a table").
rb_script_test(NAME motion_roundtrip SCRIPT tests/motion/roundtrip.py LABEL motion)
