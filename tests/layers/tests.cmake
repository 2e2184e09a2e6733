# The house's layers (label "layers"): every #include and every call
# between the libraries of src/ against the order in which CMakeLists.txt
# declares them, and no circle of calls between the files of one folder
# (tests/layers/layers.py reads the object files: run after a build).
if(Python3_Interpreter_FOUND)
  add_test(NAME layers
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/layers/layers.py
                   ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
  set_tests_properties(layers PROPERTIES LABELS "layers;refactor"
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 120)
endif()
# rb_diag_set and its field setters are the only writers of an rb_diag's
# text: a grep of src/ for any other (tests/layers/diag_writes.py)
if(Python3_Interpreter_FOUND)
  add_test(NAME diag_writes
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/layers/diag_writes.py
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(diag_writes PROPERTIES LABELS "layers;refactor"
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TIMEOUT 60)
endif()
