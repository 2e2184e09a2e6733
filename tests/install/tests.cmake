# The tool as installed and used from a PATH (label "install"): the help
# of every command against its parser, the man page and completions made
# from the same source, each exit code, and an installed tree that runs
# with the source tree out of reach.
add_test(NAME install_help
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/install/help_test.sh
                 $<TARGET_FILE:rockbolt> ${PROJECT_BINARY_DIR}/man/rockbolt.1
                 ${PROJECT_BINARY_DIR}/completion/rockbolt
                 ${PROJECT_BINARY_DIR}/completion/_rockbolt
                 ${CMAKE_CURRENT_BINARY_DIR}/install-scratch/help)
add_test(NAME install_exit_codes
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/install/exit_codes.sh
                 $<TARGET_FILE:rockbolt>
                 ${CMAKE_CURRENT_BINARY_DIR}/install-scratch/exit-codes)
set_tests_properties(install_help install_exit_codes PROPERTIES LABELS install
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
add_test(NAME install_relocated
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/install/install_test.sh
                 ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR}/install-scratch/tree
                 ${CMAKE_C_COMPILER})
set_tests_properties(install_relocated PROPERTIES LABELS install
    SKIP_RETURN_CODE 77 TIMEOUT 300)
