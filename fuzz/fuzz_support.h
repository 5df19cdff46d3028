// What the libFuzzer targets share: the repository's data directory and the
// abort that makes libFuzzer report an input breaking a contract.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace apprentice::fuzz {

// APPRENTICE_SOURCE_DIR is set by fuzz/CMakeLists.txt.
inline std::filesystem::path source_dir() { return APPRENTICE_SOURCE_DIR; }

// A violated contract is a bug: abort so that libFuzzer reports the input.
inline void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace apprentice::fuzz
