# Hostile text and files in inputs (label "hostile"): formula injection in
# CSV outputs, control characters in names, file content quoted in
# diagnostics, --sandbox, and merge's digests. See hostile_test.sh.
rb_shell_tests(PREFIX hostile SCRIPT tests/hostile/hostile_test.sh SCRATCH hostile
               LABEL hostile TIMEOUT 300
               TESTS csv_formula control_chars format_chars json_format_chars no_quote sandbox merge_digest
                     row_base_line)
