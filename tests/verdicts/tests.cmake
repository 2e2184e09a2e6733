# The verdict of a run (label "verdicts"): one judge for every command, the
# model's validity checks, and list rows that keep what they do not name.
foreach(t no_yield validity default_model gap)
  rb_script_test(NAME verdict_${t} SCRIPT tests/verdicts/verdicts.py LABEL verdicts
                 AFTER ${t} TIMEOUT 300)
endforeach()
add_executable(judge_probe ${PROJECT_SOURCE_DIR}/tests/verdicts/judge_probe.c)
rb_target_defaults(judge_probe)
target_link_libraries(judge_probe PRIVATE rb_all PkgConfig::CJSON)
rb_script_test(NAME verdict_overrides SCRIPT tests/verdicts/overrides.py LABEL verdicts)
rb_script_test(NAME verdict_concrete SCRIPT tests/verdicts/concrete.py LABEL verdicts)
# 1000 random cases through check, batch (files and a list), merge and the
# design searches' run: about 110 s in a release build on two cores. The
# sanitizer build draws the first 100 of the same sample: the full draw
# took over 10 minutes under ASan, and the property is the release build's
# to prove, the sanitizers' to run clean.
if(RB_SANITIZE)
  set(RB_PROPERTY_CASES 100)
else()
  set(RB_PROPERTY_CASES 1000)
endif()
rb_script_test(NAME verdict_property SCRIPT tests/verdicts/property.py LABEL verdicts
               TOOLS $<TARGET_FILE:judge_probe> AFTER ${RB_PROPERTY_CASES} TIMEOUT 1800)
# the confirmation of marginal passes at tighter tolerances
rb_script_test(NAME verdict_confirm SCRIPT tests/verdicts/confirm.py LABEL verdicts
               TOOLS $<TARGET_FILE:judge_probe>)
