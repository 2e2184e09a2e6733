# rockbolt motion end to end: its AT2 and CSV files hold the floor the
# solver sees (an independent building filter), and read back as records
# they give the case's own results (docs/motion.md, "Motions for a table").
rb_script_test(NAME motion_roundtrip SCRIPT tests/motion/roundtrip.py LABEL motion)
# A given waveform judged against a user's RRS (GR-63-CORE, low_cutoff,
# max_ratio) and the exit code, against a TRS computed in the test.
rb_script_test(NAME motion_accept SCRIPT tests/motion/accept.py LABEL motion)
