# A case in US customary units: no SI unit in any output for people
# (docs/case-format.md, Output units).
rb_script_test(NAME units_us_outputs SCRIPT tests/units/us_units.py LABEL units)
