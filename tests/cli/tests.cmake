# End-to-end tests of the rockbolt executable (label "cli"): exit codes,
# JSON and text reports that agree, all-or-nothing output files. jsonget
# is the small JSON reader the tests use to pick values out of a report.
add_executable(jsonget ${PROJECT_SOURCE_DIR}/tests/cli/jsonget.c)
rb_target_defaults(jsonget)
target_link_libraries(jsonget PRIVATE PkgConfig::CJSON)

rb_shell_tests(PREFIX cli SCRIPT tests/cli/cli_test.sh SCRATCH cli LABEL cli TIMEOUT 300
               TOOLS $<TARGET_FILE:jsonget>
               TESTS help usage harmonic stdout elcentro unwritable preserved
                     history init template solver_error free_standing design
                     design_threads figures titles)
# the reports' numbers: the text's against the JSON's, a suite's, US units, the
# El Centro scaling, the history's rows, the design's relations
foreach(t consistency suite units elcentro history design)
  rb_script_test(NAME cli_numbers_${t} SCRIPT tests/cli/numbers.py LABEL cli AFTER ${t})
endforeach()
# the progress line while a suite is generated, on a pseudo-terminal
rb_script_test(NAME cli_progress SCRIPT tests/cli/progress.py LABEL cli TIMEOUT 300)
