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
