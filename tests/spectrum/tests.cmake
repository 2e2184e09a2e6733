# rockbolt spectrum, synthetic motions and init --ac156 end to end
# (docs/motion.md).
rb_script_test(NAME spectrum_cli SCRIPT tests/spectrum/spectrum.py LABEL spectrum)
# The triaxial AC156 suites (S_DS 1.0 g on the roof, 2.0 g at grade) as a
# laboratory accepts them, checked apart from the generator.
add_executable(synth_sets ${PROJECT_SOURCE_DIR}/tests/spectrum/synth_sets.c)
rb_target_defaults(synth_sets)
target_link_libraries(synth_sets PRIVATE rb_all)
add_test(NAME synth_sets COMMAND synth_sets)
set_tests_properties(synth_sets PROPERTIES LABELS spectrum TIMEOUT 600
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# IEEE 693 triaxial sets (Moderate, at 5 % and 2 %) as a laboratory
# accepts them, checked apart from the generator.
add_executable(synth_ieee693 ${PROJECT_SOURCE_DIR}/tests/spectrum/synth_ieee693.c)
rb_target_defaults(synth_ieee693)
target_link_libraries(synth_ieee693 PRIVATE rb_all)
add_test(NAME synth_ieee693 COMMAND synth_ieee693)
set_tests_properties(synth_ieee693 PROPERTIES LABELS spectrum TIMEOUT 600
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
