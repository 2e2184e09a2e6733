# Refactors move no number (label "refactor"): the JSON report of every
# case in cases/ and tests/, and the other commands' JSON on the runs of
# tests/refactor/outputs.txt, against tests/refactor/reports.sha256.
add_test(NAME refactor_reports
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/refactor/reports.sh $<TARGET_FILE:rockbolt>
                 ${CMAKE_CURRENT_BINARY_DIR}/refactor-scratch)
set_tests_properties(refactor_reports PROPERTIES LABELS refactor
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 900)
