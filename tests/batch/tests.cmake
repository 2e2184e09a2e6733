# End-to-end tests of "rockbolt batch" and "rockbolt merge" (label "batch"):
# every output file, the exit codes, determinism across thread counts and
# across shards merged, JUnit well-formedness.
set(RB_BATCH_TESTS outputs determinism shards errors usage reports design fragility)
foreach(t ${RB_BATCH_TESTS})
  add_test(NAME batch_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/batch/batch_test.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/batch-scratch/${t})
  set_tests_properties(batch_${t} PROPERTIES LABELS batch
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()

# What a CI needs (tests/batch/ci_test.sh): JUnit names stable when a row is
# inserted, lists in cp1252 or with semicolons, progress on a terminal only.
set(RB_CI_TESTS junit_names encoding separators design_progress)
foreach(t ${RB_CI_TESTS})
  add_test(NAME ci_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/batch/ci_test.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/ci-scratch/${t})
  set_tests_properties(ci_${t} PROPERTIES LABELS batch
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
