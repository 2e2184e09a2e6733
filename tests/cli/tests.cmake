# End-to-end tests of the rockbolt executable (label "cli"): exit codes,
# JSON and text reports that agree, all-or-nothing output files. jsonget
# is the small JSON reader the tests use to pick values out of a report.
add_executable(jsonget ${PROJECT_SOURCE_DIR}/tests/cli/jsonget.c)
rb_target_defaults(jsonget)
target_link_libraries(jsonget PRIVATE PkgConfig::CJSON)

set(RB_CLI_TESTS help usage harmonic consistency stdout elcentro unwritable
    preserved history init template solver_error
    free_standing design design_threads suite figures units)
foreach(t ${RB_CLI_TESTS})
  add_test(NAME cli_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/cli/cli_test.sh ${t}
                   $<TARGET_FILE:rockbolt> $<TARGET_FILE:jsonget>
                   ${CMAKE_CURRENT_BINARY_DIR}/cli-scratch/${t})
  set_tests_properties(cli_${t} PROPERTIES LABELS cli
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
