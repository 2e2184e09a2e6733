# Validation against the thesis (label "validation"): rb_validate runs the
# cases of cases/thesis/ and compares them with the thesis values of
# cases/thesis/expected.csv. From the source root,
#   ./build/rb_validate --write docs/validation.md
# regenerates the published report; the ctest writes its copy into the
# build tree and fails when a row that must agree leaves its tolerance.
file(GLOB RB_VALIDATE_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/validation/*.c)
add_executable(rb_validate ${RB_VALIDATE_SOURCES})
rb_target_defaults(rb_validate)
target_link_libraries(rb_validate PRIVATE rb_all)
add_test(NAME validation
         COMMAND rb_validate --root ${PROJECT_SOURCE_DIR}
                 --write ${CMAKE_CURRENT_BINARY_DIR}/validation.md)
set_tests_properties(validation PROPERTIES LABELS validation
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 900)
# Samples inserted on a record's own straight lines (dt/10) change no
# governing result beyond 1e-6, with and without a building (the floor is
# exact between samples): every shipped record, 5, 8 and 10 Hz buildings.
rb_script_test(NAME validation_convergence SCRIPT tests/validation/convergence.py
               LABEL validation)
# the Taylor steps against Dormand-Prince at 1e-9 on every shipped case
rb_script_test(NAME validation_integrators SCRIPT tests/validation/integrators.py
               LABEL validation)
# Two check points a step (the default) held to 4, 8 and 16 over 120
# random cabinets, where those agree among themselves (docs/solver.md,
# "Check points a step"); the program is a benchmark study as well.
add_test(NAME validation_check_points COMMAND check_points_study 120 2 2e-5)
set_tests_properties(validation_check_points PROPERTIES LABELS validation
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
