# Robustness of the executable towards its files (label "robustness"):
# unwritable outputs refused before solving, inputs never modified. See
# robustness.sh for what each test checks.
set(RB_ROBUSTNESS_TESTS unwritable inputs over_inputs)
foreach(t ${RB_ROBUSTNESS_TESTS})
  add_test(NAME robustness_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/robustness/robustness.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/robustness-scratch/${t})
  set_tests_properties(robustness_${t} PROPERTIES LABELS robustness
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 120)
endforeach()

# What the executable writes and leaves behind (outputs.sh): clashes with
# inputs and other outputs, special files, long names, signals, reasons.
set(RB_OUTPUT_TESTS fanout clashes special names signals reasons)
foreach(t ${RB_OUTPUT_TESTS})
  add_test(NAME outputs_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/robustness/outputs.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/outputs-scratch/${t})
  set_tests_properties(outputs_${t} PROPERTIES LABELS robustness
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 120)
endforeach()

# Property: the exit code and every file written are the same whatever
# other outputs are asked for (random cases and option sets, 40 s budget).
add_test(NAME outputs_property
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/robustness/outputs_property.sh
                 $<TARGET_FILE:rockbolt>
                 ${CMAKE_CURRENT_BINARY_DIR}/outputs-scratch/property 40)
set_tests_properties(outputs_property PROPERTIES LABELS robustness
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 240)
