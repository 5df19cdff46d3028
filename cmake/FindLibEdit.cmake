# Finds libedit (Debian: libedit-dev) and defines the imported target
# LibEdit::LibEdit. Used by the build and by the installed
# apprenticeConfig.cmake.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(PC_LibEdit QUIET libedit)
endif()
find_path(LibEdit_INCLUDE_DIR histedit.h HINTS ${PC_LibEdit_INCLUDE_DIRS})
find_library(LibEdit_LIBRARY edit HINTS ${PC_LibEdit_LIBRARY_DIRS})
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LibEdit REQUIRED_VARS LibEdit_LIBRARY LibEdit_INCLUDE_DIR)
if(LibEdit_FOUND AND NOT TARGET LibEdit::LibEdit)
  add_library(LibEdit::LibEdit UNKNOWN IMPORTED)
  set_target_properties(LibEdit::LibEdit PROPERTIES
    IMPORTED_LOCATION "${LibEdit_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LibEdit_INCLUDE_DIR}")
  if(PC_LibEdit_CFLAGS_OTHER)
    set_target_properties(LibEdit::LibEdit PROPERTIES INTERFACE_COMPILE_OPTIONS "${PC_LibEdit_CFLAGS_OTHER}")
  endif()
endif()
mark_as_advanced(LibEdit_INCLUDE_DIR LibEdit_LIBRARY)
