# Version header, the installable library, and the install rules.
# Included from CMakeLists.txt after the targets rb_core, rb_io and rockbolt.
include(GNUInstallDirs)

# The version, from project(VERSION): one place for --version, the reports
# and the library.
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.h.in
               ${PROJECT_BINARY_DIR}/include/rockbolt/version.h @ONLY)
target_include_directories(rb_core PUBLIC
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>)

# The data directory of the configured prefix: the last place the data is
# looked for (include/rockbolt/datadir.h).
set_property(SOURCE ${PROJECT_SOURCE_DIR}/src/io/datadir.c APPEND PROPERTY
    COMPILE_DEFINITIONS
    RB_INSTALL_DATADIR="${CMAKE_INSTALL_FULL_DATADIR}/rockbolt")

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
target_include_directories(rockbolt PRIVATE ${PROJECT_SOURCE_DIR}/src/cli)
