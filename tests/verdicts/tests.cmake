# The verdict of a run (label "verdicts"): one judge for every command, the
# model's validity checks, and list rows that keep what they do not name.
rb_shell_tests(PREFIX verdict SCRIPT tests/verdicts/verdict_test.sh SCRATCH verdict
               LABEL verdicts TIMEOUT 300 TOOLS $<TARGET_FILE:jsonget>
               TESTS no_yield validity default_model gap)
add_executable(judge_probe ${PROJECT_SOURCE_DIR}/tests/verdicts/judge_probe.c)
rb_target_defaults(judge_probe)
target_link_libraries(judge_probe PRIVATE rb_all PkgConfig::CJSON)
rb_script_test(NAME verdict_overrides SCRIPT tests/verdicts/overrides.py LABEL verdicts)
rb_script_test(NAME verdict_concrete SCRIPT tests/verdicts/concrete.py LABEL verdicts)
# 1000 random cases through check, batch (files and a list) and the
# design searches' run: about 30 s here
rb_script_test(NAME verdict_property SCRIPT tests/verdicts/property.py LABEL verdicts
               TOOLS $<TARGET_FILE:judge_probe> AFTER 1000 TIMEOUT 1800)
# the confirmation of marginal passes at tighter tolerances
rb_script_test(NAME verdict_confirm SCRIPT tests/verdicts/confirm.py LABEL verdicts
               TOOLS $<TARGET_FILE:judge_probe>)
