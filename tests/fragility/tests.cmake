# rockbolt fragility end to end (docs/fragility.md).
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME fragility_cli
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/fragility/fragility.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/fragility-scratch)
  set_tests_properties(fragility_cli PROPERTIES LABELS fragility
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
endif()
# batch --fragility against fragility, row by row, and its determinism
if(Python3_Interpreter_FOUND)
  add_test(NAME fragility_batch_property
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/fragility/batch_property.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/fragility-batch-scratch)
  set_tests_properties(fragility_batch_property PROPERTIES LABELS fragility
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
endif()
# --sweep-gap: each point the fragility of the case with that gap ratio;
# the figure; bad ranges refused
if(Python3_Interpreter_FOUND)
  add_test(NAME fragility_sweep_gap
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/fragility/sweep.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/fragility-sweep-scratch)
  set_tests_properties(fragility_sweep_gap PROPERTIES LABELS fragility
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
endif()
