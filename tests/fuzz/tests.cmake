# Fuzzing of the input side (case loader and record readers).
#
# Always: a replay driver per harness (fuzz_replay_<harness>, built with the
# normal compiler and flags) and one ctest per reproducer file in
# tests/fuzz/regressions/<harness>/ (label fuzz-regression), so a crash once
# found by the fuzzer stays fixed in every build, clang or not.
#
# With -DRB_FUZZ=ON (clang only): the libFuzzer harnesses fuzz_<harness>,
# linked against their own copy of the io and core sources compiled with
# coverage instrumentation, ASan and UBSan. tests/fuzz/run.sh runs them.
set(RB_FUZZ_HARNESSES case at2 cosmos columns table list merge)
set(RB_FUZZ_DIR ${PROJECT_SOURCE_DIR}/tests/fuzz)

foreach(h ${RB_FUZZ_HARNESSES})
  add_executable(fuzz_replay_${h} ${RB_FUZZ_DIR}/fuzz_${h}.c
                 ${RB_FUZZ_DIR}/fuzz_common.c ${RB_FUZZ_DIR}/fuzz_driver.c)
  rb_target_defaults(fuzz_replay_${h})
  target_link_libraries(fuzz_replay_${h} PRIVATE rb_all)
  # The committed seeds too: keeps the driver and the harness invariants
  # honest in every build, even while regressions/<harness>/ is empty.
  if(EXISTS ${RB_FUZZ_DIR}/seeds/${h})
    add_test(NAME fuzz_seeds_${h} COMMAND fuzz_replay_${h} ${RB_FUZZ_DIR}/seeds/${h})
    set_tests_properties(fuzz_seeds_${h} PROPERTIES LABELS fuzz-regression
        TIMEOUT 60 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  endif()
  file(GLOB repros CONFIGURE_DEPENDS ${RB_FUZZ_DIR}/regressions/${h}/*)
  foreach(repro ${repros})
    get_filename_component(rname ${repro} NAME)
    add_test(NAME fuzz_regression_${h}_${rname}
             COMMAND fuzz_replay_${h} ${repro})
    # Reproducers include hangs: a generous bound still fails fast.
    set_tests_properties(fuzz_regression_${h}_${rname} PROPERTIES
        LABELS fuzz-regression TIMEOUT 30 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  endforeach()
endforeach()

if(RB_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "RB_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_C_COMPILER=clang")
  endif()
  set(RB_FUZZ_FLAGS -fsanitize=fuzzer-no-link,address,undefined
      -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  # Every library below the command line, instrumented: a list row reaches
  # the batch, a case the synthetic generator, and so on down.
  file(GLOB RB_FUZZ_LIB_SOURCES CONFIGURE_DEPENDS
       ${PROJECT_SOURCE_DIR}/src/util/*.c ${PROJECT_SOURCE_DIR}/src/core/*.c
       ${PROJECT_SOURCE_DIR}/src/motion/*.c ${PROJECT_SOURCE_DIR}/src/record/*.c
       ${PROJECT_SOURCE_DIR}/src/design/*.c ${PROJECT_SOURCE_DIR}/src/synth/*.c
       ${PROJECT_SOURCE_DIR}/src/case/*.c ${PROJECT_SOURCE_DIR}/src/report/*.c
       ${PROJECT_SOURCE_DIR}/src/output/*.c ${PROJECT_SOURCE_DIR}/src/codes/*.c
       ${PROJECT_SOURCE_DIR}/src/fragility/*.c ${PROJECT_SOURCE_DIR}/src/plot/*.c
       ${PROJECT_SOURCE_DIR}/src/run/*.c ${PROJECT_SOURCE_DIR}/src/batch/*.c)
  add_library(rb_fuzz_lib STATIC ${RB_FUZZ_LIB_SOURCES}
              ${PROJECT_BINARY_DIR}/generated/template_builtin.c)
  rb_target_defaults(rb_fuzz_lib)
  target_include_directories(rb_fuzz_lib PUBLIC ${PROJECT_SOURCE_DIR}/src
                             ${PROJECT_BINARY_DIR}/include)
  target_compile_options(rb_fuzz_lib PRIVATE ${RB_FUZZ_FLAGS})
  target_link_libraries(rb_fuzz_lib PUBLIC PkgConfig::YAML PkgConfig::CJSON
                        PkgConfig::FFTW PkgConfig::NETTLE Threads::Threads m)
  foreach(h ${RB_FUZZ_HARNESSES})
    add_executable(fuzz_${h} ${RB_FUZZ_DIR}/fuzz_${h}.c ${RB_FUZZ_DIR}/fuzz_common.c)
    rb_target_defaults(fuzz_${h})
    target_compile_options(fuzz_${h} PRIVATE ${RB_FUZZ_FLAGS})
    target_link_options(fuzz_${h} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_libraries(fuzz_${h} PRIVATE rb_fuzz_lib)
  endforeach()
endif()
