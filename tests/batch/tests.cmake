# End-to-end tests of "rockbolt batch" and "rockbolt merge" (label "batch"):
# every output file, the exit codes, determinism across thread counts and
# across shards merged, JUnit well-formedness.
rb_shell_tests(PREFIX batch SCRIPT tests/batch/batch_test.sh SCRATCH batch LABEL batch
               TIMEOUT 300
               TESTS outputs determinism shards errors usage reports design fragility)

# What a CI needs (tests/batch/ci_test.sh): JUnit names stable when a row is
# inserted, lists in cp1252 or with semicolons, progress on a terminal only.
rb_shell_tests(PREFIX ci SCRIPT tests/batch/ci_test.sh SCRATCH ci LABEL batch TIMEOUT 300
               TESTS junit_names encoding separators design_progress)

# Equipment lists whose columns are any case key (tests/batch/list_test.sh):
# a 50-row list checked against formulas worked out in the test, multi-line
# cells, the values that follow the bolt's size, errors at their cells.
rb_shell_tests(PREFIX list SCRIPT tests/batch/list_test.sh SCRATCH list LABEL batch
               TIMEOUT 300 TESTS columns multiline sizes errors)
