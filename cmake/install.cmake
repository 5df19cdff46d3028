# What `cmake --install build --prefix P` puts under P:
#   bin/apprentice                         the CLI
#   lib/libapprentice_*.a                  one static library per module
#   include/apprentice/face/apprentice.h   the public face, and the headers it includes (docs/install.md)
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
# The public face (src/face/apprentice.h) and the headers it includes, and
# theirs: the types it names, and no other. Found by following the
# #include "module/file.h" lines, so that the list cannot drift from the code.
set(apprentice_public_headers "")
set(apprentice_header_queue face/apprentice.h)
while(apprentice_header_queue)
  list(POP_FRONT apprentice_header_queue header)
  if(header IN_LIST apprentice_public_headers)
    continue()
  endif()
  list(APPEND apprentice_public_headers ${header})
  file(STRINGS ${PROJECT_SOURCE_DIR}/src/${header} includes REGEX "^#include \"[a-z_]+/[a-z_0-9]+\\.h\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    list(APPEND apprentice_header_queue ${included})
  endforeach()
endwhile()
foreach(header IN LISTS apprentice_public_headers)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${header})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/apprentice/${folder})
endforeach()
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
