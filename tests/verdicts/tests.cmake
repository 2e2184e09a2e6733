# The verdict of a run (label "verdicts"): one judge for every command, the
# model's validity checks, and list rows that keep what they do not name.
foreach(t no_yield validity)
  add_test(NAME verdict_${t}
           COMMAND sh ${PROJECT_SOURCE_DIR}/tests/verdicts/verdict_test.sh ${t}
                   $<TARGET_FILE:rockbolt> $<TARGET_FILE:jsonget>
                   ${CMAKE_CURRENT_BINARY_DIR}/verdict-scratch/${t})
  set_tests_properties(verdict_${t} PROPERTIES LABELS verdicts
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 300)
endforeach()
add_executable(judge_probe ${PROJECT_SOURCE_DIR}/tests/verdicts/judge_probe.c)
rb_target_defaults(judge_probe)
target_link_libraries(judge_probe PRIVATE rb_all PkgConfig::CJSON)
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME verdict_overrides
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/verdicts/overrides.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/verdict-scratch/overrides)
  set_tests_properties(verdict_overrides PROPERTIES LABELS verdicts
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
  add_test(NAME verdict_concrete
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/verdicts/concrete.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/verdict-scratch/concrete)
  set_tests_properties(verdict_concrete PROPERTIES LABELS verdicts
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
  # 1000 random cases through check, batch (files and a list) and the
  # design searches' run: about 30 s here
  add_test(NAME verdict_property
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/verdicts/property.py
                   $<TARGET_FILE:rockbolt> $<TARGET_FILE:judge_probe>
                   ${CMAKE_CURRENT_BINARY_DIR}/verdict-scratch/property 1000)
  set_tests_properties(verdict_property PROPERTIES LABELS verdicts
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 1800)
endif()
