# Robustness of the executable towards its files (label "robustness"):
# unwritable outputs refused before solving, inputs never modified. See
# robustness.sh for what each test checks.
rb_shell_tests(PREFIX robustness SCRIPT tests/robustness/robustness.sh SCRATCH robustness
               LABEL robustness TIMEOUT 120 TESTS unwritable inputs over_inputs)

# What the executable writes and leaves behind (outputs.sh): clashes with
# inputs and other outputs, special files, long names, signals, reasons.
rb_shell_tests(PREFIX outputs SCRIPT tests/robustness/outputs.sh SCRATCH outputs
               LABEL robustness TIMEOUT 120
               TESTS fanout clashes special names signals reasons)

# Property: the exit code and every file written are the same whatever
# other outputs are asked for (random cases and option sets, 40 s budget).
add_test(NAME outputs_property
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/robustness/outputs_property.sh
                 $<TARGET_FILE:rockbolt>
                 ${CMAKE_CURRENT_BINARY_DIR}/outputs-scratch/property 40)
set_tests_properties(outputs_property PROPERTIES LABELS robustness
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 240)

# The exit code of every shipped and bad-input case is the same with and
# without --json: 115 cases in about 20 s in an optimised build on a
# shared two-core machine. Label exitcodes: tests/valgrind.sh does not run
# it, and ctest -L exitcodes runs it alone.
add_test(NAME json_exit_codes
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/robustness/json_exit_codes.sh
                 $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/json-exit-scratch)
set_tests_properties(json_exit_codes PROPERTIES LABELS exitcodes
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
