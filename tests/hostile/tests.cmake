# Hostile text and files in inputs (label "hostile"): formula injection in
# CSV outputs, control characters in names, file content quoted in
# diagnostics, --sandbox, and merge's digests. See hostile_test.sh.
set(RB_HOSTILE_TESTS csv_formula control_chars no_quote sandbox merge_digest)
foreach(t ${RB_HOSTILE_TESTS})
  add_test(NAME hostile_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/hostile/hostile_test.sh ${t}
                   $<TARGET_FILE:rockbolt>
                   ${CMAKE_CURRENT_BINARY_DIR}/hostile-scratch/${t})
  set_tests_properties(hostile_${t} PROPERTIES LABELS hostile
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
