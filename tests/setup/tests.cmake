# The README's set-up commands and .ci/run agree (label "cli").
add_test(NAME setup_readme_commands
         COMMAND ${CMAKE_COMMAND} -P ${PROJECT_SOURCE_DIR}/tests/setup/readme_commands.cmake)
set_tests_properties(setup_readme_commands PROPERTIES LABELS cli
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
