# Work and resource bounds that need more than one case file: inputs that
# must never block (FIFOs), record files over the byte limit, and batch
# memory against the length of the list (docs/robustness.md).
set(RB_LIMITS_TESTS fifo_batch fifo_check fifo_list fifo_base record_bytes
    batch_tmpdir batch_memory)
foreach(t ${RB_LIMITS_TESTS})
  add_test(NAME limits_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/limits/limits.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/limits-scratch/${t})
  set_tests_properties(limits_${t} PROPERTIES LABELS robustness
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 180)
endforeach()
