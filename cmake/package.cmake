# Version header, the installable library, and the install rules.
# Included from CMakeLists.txt after the libraries and rockbolt.
include(GNUInstallDirs)

# The version, from project(VERSION): one place for --version, the reports
# and the library.
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.h.in
               ${PROJECT_BINARY_DIR}/include/rockbolt/version.h @ONLY)
target_include_directories(rb_core PUBLIC
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>)

# Where the data is installed: relative to the binary's directory, the first
# place an installed rockbolt looks, and the configured prefix's, the last
# (include/rockbolt/datadir.h).
file(RELATIVE_PATH RB_DATA_FROM_BIN ${CMAKE_INSTALL_FULL_BINDIR}
     ${CMAKE_INSTALL_FULL_DATADIR}/rockbolt)
set_property(SOURCE ${PROJECT_SOURCE_DIR}/src/util/datadir.c APPEND PROPERTY
    COMPILE_DEFINITIONS
    RB_INSTALL_DATADIR="${CMAKE_INSTALL_FULL_DATADIR}/rockbolt"
    RB_DATA_FROM_BIN="${RB_DATA_FROM_BIN}")

# The help texts, the man page and the bash and zsh completions, from the
# one source src/cli/help.txt.
add_executable(rb_helpgen ${PROJECT_SOURCE_DIR}/tools/helpgen.c)
set_target_properties(rb_helpgen PROPERTIES INTERPROCEDURAL_OPTIMIZATION OFF)
add_custom_command(
  OUTPUT ${PROJECT_BINARY_DIR}/generated/cli_help_text.c
         ${PROJECT_BINARY_DIR}/man/rockbolt.1
         ${PROJECT_BINARY_DIR}/completion/rockbolt
         ${PROJECT_BINARY_DIR}/completion/_rockbolt
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/generated
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/completion
  COMMAND rb_helpgen ${PROJECT_SOURCE_DIR}/src/cli/help.txt ${PROJECT_VERSION}
          ${PROJECT_BINARY_DIR}/generated/cli_help_text.c
          ${PROJECT_BINARY_DIR}/man/rockbolt.1
          ${PROJECT_BINARY_DIR}/completion/rockbolt
          ${PROJECT_BINARY_DIR}/completion/_rockbolt
  DEPENDS rb_helpgen ${PROJECT_SOURCE_DIR}/src/cli/help.txt
  COMMENT "Generating the help texts and rockbolt.1 from src/cli/help.txt")
target_sources(rockbolt PRIVATE ${PROJECT_BINARY_DIR}/generated/cli_help_text.c)

# rockbolt-case(5), the case file's manual, from docs/case-format.md: one
# source, so that the page and the document cannot disagree. Built with the
# tool, so that every build that has one has its manual.
add_executable(rb_mdman ${PROJECT_SOURCE_DIR}/tools/mdman.c)
set_target_properties(rb_mdman PROPERTIES INTERPROCEDURAL_OPTIMIZATION OFF)
target_compile_options(rb_mdman PRIVATE ${RB_WARNINGS})
add_custom_command(
  OUTPUT ${PROJECT_BINARY_DIR}/man/rockbolt-case.5
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
  COMMAND rb_mdman ${PROJECT_SOURCE_DIR}/docs/case-format.md
          ${PROJECT_BINARY_DIR}/man/rockbolt-case.5 rockbolt-case 5 ${PROJECT_VERSION}
          "the case files of rockbolt: keys, units, defaults and limits"
  DEPENDS rb_mdman ${PROJECT_SOURCE_DIR}/docs/case-format.md
  COMMENT "Generating rockbolt-case.5 from docs/case-format.md")
add_custom_target(rb_man_case DEPENDS ${PROJECT_BINARY_DIR}/man/rockbolt-case.5)
add_dependencies(rockbolt rb_man_case)
target_include_directories(rockbolt PRIVATE ${PROJECT_SOURCE_DIR}/src/cli)

# librockbolt, static and shared, from the sources of every library,
# compiled once more as position-independent code and without link-time
# optimisation, so that any compiler can link the archive. The tests keep
# linking the libraries of the build.
option(RB_LIBRARY "Build and install librockbolt (static and shared)" ON)
if(RB_LIBRARY)
  set(RB_LIB_SOURCES)
  foreach(tgt ${RB_LIBRARIES})
    if(TARGET ${tgt})
      get_target_property(srcs ${tgt} SOURCES)
      list(APPEND RB_LIB_SOURCES ${srcs})
    endif()
  endforeach()
  add_library(rockbolt_objects OBJECT ${RB_LIB_SOURCES})
  set_target_properties(rockbolt_objects PROPERTIES POSITION_INDEPENDENT_CODE ON
      INTERPROCEDURAL_OPTIMIZATION OFF)
  # rb_target_defaults without the sanitizers: programs outside this build
  # link the library
  target_compile_options(rockbolt_objects PRIVATE ${RB_WARNINGS})
  target_compile_definitions(rockbolt_objects PRIVATE _POSIX_C_SOURCE=200809L
      _DEFAULT_SOURCE RB_VERSION="${PROJECT_VERSION}"
      RB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(rockbolt_objects PRIVATE ${PROJECT_SOURCE_DIR}/include
      ${PROJECT_BINARY_DIR}/include ${PROJECT_SOURCE_DIR}/src)
  set(RB_LIB_DEPS PkgConfig::YAML PkgConfig::CJSON PkgConfig::NETTLE PkgConfig::FFTW
      PkgConfig::PDF Threads::Threads m)
  target_link_libraries(rockbolt_objects PRIVATE ${RB_LIB_DEPS})
  add_dependencies(rockbolt_objects rb_batch)

  add_library(rockbolt_shared SHARED $<TARGET_OBJECTS:rockbolt_objects>)
  add_library(rockbolt_static STATIC $<TARGET_OBJECTS:rockbolt_objects>)
  set_target_properties(rockbolt_shared PROPERTIES OUTPUT_NAME rockbolt
      VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
      INTERPROCEDURAL_OPTIMIZATION OFF)
  set_target_properties(rockbolt_static PROPERTIES OUTPUT_NAME rockbolt
      INTERPROCEDURAL_OPTIMIZATION OFF)
  target_link_libraries(rockbolt_shared PRIVATE ${RB_LIB_DEPS})
  install(TARGETS rockbolt_shared rockbolt_static
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

  # pkg-config and find_package(rockbolt), both relocatable: paths relative
  # to where the file itself is installed
  if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    set(RB_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
    set(RB_CMAKE_PREFIX "${CMAKE_INSTALL_PREFIX}")
  else()
    file(RELATIVE_PATH rel "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
    string(REGEX REPLACE "/$" "" rel "${rel}")
    set(RB_PC_PREFIX "\${pcfiledir}/${rel}")
    file(RELATIVE_PATH rel "/p/${CMAKE_INSTALL_LIBDIR}/cmake/rockbolt" "/p")
    string(REGEX REPLACE "/$" "" rel "${rel}")
    set(RB_CMAKE_PREFIX "\${CMAKE_CURRENT_LIST_DIR}/${rel}")
  endif()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/rockbolt.pc.in
                 ${PROJECT_BINARY_DIR}/pkg/rockbolt.pc @ONLY)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/rockbolt-config.cmake.in
                 ${PROJECT_BINARY_DIR}/pkg/rockbolt-config.cmake @ONLY)
  include(CMakePackageConfigHelpers)
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/pkg/rockbolt-config-version.cmake
      VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/pkg/rockbolt.pc
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
  install(FILES ${PROJECT_BINARY_DIR}/pkg/rockbolt-config.cmake
                ${PROJECT_BINARY_DIR}/pkg/rockbolt-config-version.cmake
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rockbolt)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/rockbolt
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
  install(FILES ${PROJECT_BINARY_DIR}/include/rockbolt/version.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rockbolt)
endif()

# The tool, its data, its manual and completions, its licence.
install(TARGETS rockbolt RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/records/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rockbolt/records)
install(FILES ${PROJECT_SOURCE_DIR}/templates/report.txt
              ${PROJECT_SOURCE_DIR}/templates/calc.txt
              ${PROJECT_SOURCE_DIR}/templates/starter.yaml
              ${PROJECT_SOURCE_DIR}/templates/ac156.yaml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rockbolt/templates)
install(FILES ${PROJECT_BINARY_DIR}/man/rockbolt.1
        DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_BINARY_DIR}/man/rockbolt-case.5
        DESTINATION ${CMAKE_INSTALL_MANDIR}/man5)
install(FILES ${PROJECT_BINARY_DIR}/completion/rockbolt
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES ${PROJECT_BINARY_DIR}/completion/_rockbolt
        DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/site-functions)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
# the documents the README and the manuals refer to, with their figures
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
