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

