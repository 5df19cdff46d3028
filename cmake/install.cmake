# What `cmake --install build --prefix P` puts under P:
#   bin/apprentice                         the CLI
#   lib/libapprentice_*.a                  one static library per module
#   include/apprentice/<module>/*.h        the headers (docs/install.md)
#   lib/cmake/apprentice/                  the CMake package: find_package(apprentice)
#   share/apprentice/                      domains, scenarios, prompt templates
#   share/bash-completion/completions/apprentice, share/man/man1/apprentice.1
#   lib/python3/dist-packages/apprentice/  the Python module, when built
include(CMakePackageConfigHelpers)

set(APPRENTICE_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/apprentice)
set(APPRENTICE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/apprentice)

# apprentice::apprentice: every module at once.
get_property(apprentice_modules GLOBAL PROPERTY APPRENTICE_MODULES)
add_library(apprentice_all INTERFACE)
target_link_libraries(apprentice_all INTERFACE ${apprentice_modules})
set_target_properties(apprentice_all PROPERTIES EXPORT_NAME apprentice)
add_library(apprentice::apprentice ALIAS apprentice_all)
install(TARGETS apprentice_all EXPORT apprenticeTargets)

install(TARGETS apprentice RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# session.h is the agent's own; every other header may be included.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/apprentice
        FILES_MATCHING PATTERN "*.h" PATTERN "session.h" EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${APPRENTICE_INSTALL_DATADIR})

install(EXPORT apprenticeTargets NAMESPACE apprentice:: DESTINATION ${APPRENTICE_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/apprenticeConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/apprenticeConfig.cmake
  INSTALL_DESTINATION ${APPRENTICE_INSTALL_CMAKEDIR}
  PATH_VARS APPRENTICE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/apprenticeConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/cmake/apprenticeConfig.cmake
  ${PROJECT_BINARY_DIR}/cmake/apprenticeConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindWordNet.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindLibEdit.cmake
  DESTINATION ${APPRENTICE_INSTALL_CMAKEDIR})

# The man page, made from the program's own --help by scripts/make-manpage.py.
set(APPRENTICE_MANPAGE ${PROJECT_BINARY_DIR}/apprentice.1)
add_custom_command(OUTPUT ${APPRENTICE_MANPAGE}
  COMMAND ${APPRENTICE_PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make-manpage.py $<TARGET_FILE:apprentice>
          -o ${APPRENTICE_MANPAGE}
  DEPENDS apprentice ${PROJECT_SOURCE_DIR}/scripts/make-manpage.py
  COMMENT "Writing the man page apprentice.1")
add_custom_target(apprentice_manpage ALL DEPENDS ${APPRENTICE_MANPAGE})
install(FILES ${APPRENTICE_MANPAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/completions/apprentice.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME apprentice)

# make test: the example program builds against the installed package. In
# the release build only: an ASan+UBSan installation would need the
# sanitizer flags in every program that links it.
if(APPRENTICE_TESTS AND NOT APPRENTICE_SANITIZE)
  add_test(NAME install.example
    COMMAND ${PROJECT_SOURCE_DIR}/examples/build-against-install.sh ${PROJECT_BINARY_DIR}
            ${PROJECT_BINARY_DIR}/install-test)
  set_tests_properties(install.example PROPERTIES TIMEOUT 600
    ENVIRONMENT "CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}")
endif()
