# The bad-input catalogue: one ctest per tests/errors/NN-name.yaml, checking
# the exit code and the first diagnostic line of `rockbolt check` against
# NN-name.expect (see run_error_case.sh). Files under include/ are helpers.
file(GLOB RB_ERROR_CASES CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/tests/errors/[0-9][0-9]-*.yaml
     ${PROJECT_SOURCE_DIR}/tests/errors/[0-9][0-9][0-9]-*.yaml)
foreach(case_file ${RB_ERROR_CASES})
  get_filename_component(name ${case_file} NAME_WE)
  add_test(NAME error_${name}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/errors/run_error_case.sh
                   $<TARGET_FILE:rockbolt> tests/errors/${name}.yaml
                   tests/errors/${name}.expect)
  set_tests_properties(error_${name} PROPERTIES LABELS errors
                       WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endforeach()
