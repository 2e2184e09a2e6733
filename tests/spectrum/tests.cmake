# rockbolt spectrum, synthetic motions and init --ac156 end to end
# (docs/motion.md).
rb_script_test(NAME spectrum_cli SCRIPT tests/spectrum/spectrum.py LABEL spectrum)
