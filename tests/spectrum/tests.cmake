# rockbolt spectrum, synthetic motions and init --ac156 end to end
# (docs/motion.md).
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME spectrum_cli
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/spectrum/spectrum.py
                   $<TARGET_FILE:rockbolt> ${CMAKE_CURRENT_BINARY_DIR}/spectrum-scratch)
  set_tests_properties(spectrum_cli PROPERTIES LABELS spectrum
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 600)
endif()
