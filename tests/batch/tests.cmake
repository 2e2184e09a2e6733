# End-to-end tests of "rockbolt batch" and "rockbolt merge" (label "batch"):
# every output file, the exit codes, determinism across thread counts and
# across shards merged, JUnit well-formedness.
set(RB_BATCH_TESTS outputs determinism shards errors usage reports design)
foreach(t ${RB_BATCH_TESTS})
  add_test(NAME batch_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/batch/batch_test.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/batch-scratch/${t})
  set_tests_properties(batch_${t} PROPERTIES LABELS batch
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
