# Finds WordNet's C library (Debian: wordnet-dev) and defines the imported
# target WordNet::WordNet. Used by the build and by the installed
# apprenticeConfig.cmake, so that a program linking apprentice::language
# finds it the same way.
find_path(WordNet_INCLUDE_DIR wn.h)
find_library(WordNet_LIBRARY wordnet)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(WordNet REQUIRED_VARS WordNet_LIBRARY WordNet_INCLUDE_DIR)
if(WordNet_FOUND AND NOT TARGET WordNet::WordNet)
  add_library(WordNet::WordNet UNKNOWN IMPORTED)
  set_target_properties(WordNet::WordNet PROPERTIES
    IMPORTED_LOCATION "${WordNet_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${WordNet_INCLUDE_DIR}")
endif()
mark_as_advanced(WordNet_INCLUDE_DIR WordNet_LIBRARY)
