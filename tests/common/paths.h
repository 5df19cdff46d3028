// Where the tests find their data: the checkout (APPRENTICE_SOURCE_DIR) and
// the shared data next to it (APPRENTICE_SHARED_DIR, ../shared), which a
// user's clone does not have. A test that needs ../shared skips without it,
// except under CI=true, where a skip would hide a broken setup: there it
// fails (APPRENTICE_REQUIRE_SHARED).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace apprentice::testing {

std::filesystem::path source_path(std::string_view relative);
std::filesystem::path shared_path(std::string_view relative);
// A shipped scenario by name: "tidy-kitchen" -> data/scenarios/tidy-kitchen.yaml.
std::filesystem::path scenario_path(std::string_view name);
// The recorded GPT-3 goal responses of the STARS experiment (../shared).
std::filesystem::path corpus_path();
bool have_corpus();

// The word vectors the build converted (build/vectors/; absent when the
// npm packages were not installed).
std::filesystem::path built_vectors_path();

// Whether the environment says this is a CI run (CI set to "true" or "1").
bool in_ci();

}  // namespace apprentice::testing

// Skips the test when `file` (a file of ../shared) is absent; fails it
// instead under CI=true. Use at the top of a test body or SetUp.
#define APPRENTICE_REQUIRE_SHARED(file)                                                              \
  do {                                                                                               \
    const ::std::filesystem::path apprentice_required_ = (file);                                     \
    if (!::std::filesystem::exists(apprentice_required_)) {                                          \
      if (::apprentice::testing::in_ci())                                                            \
        FAIL() << "CI=true but " << apprentice_required_ << " is absent (../shared must be present)"; \
      GTEST_SKIP() << "no " << apprentice_required_ << " (../shared is not part of a clone)";        \
    }                                                                                                \
  } while (0)

// The STARS corpus of recorded GPT-3 responses, as above.
#define SKIP_WITHOUT_CORPUS() APPRENTICE_REQUIRE_SHARED(::apprentice::testing::corpus_path())

// Skips the test when the build has no word vectors (scripts/install-deps.sh
// was not run before the build); fails it instead under CI=true, where
// install-deps always runs.
#define APPRENTICE_REQUIRE_VECTORS()                                                                    \
  do {                                                                                                  \
    const ::std::filesystem::path apprentice_vectors_ = ::apprentice::testing::built_vectors_path();    \
    if (!::std::filesystem::exists(apprentice_vectors_)) {                                              \
      if (::apprentice::testing::in_ci()) FAIL() << "CI=true but the build has no " << apprentice_vectors_; \
      GTEST_SKIP() << "no " << apprentice_vectors_ << " (run scripts/install-deps.sh, then build)";     \
    }                                                                                                   \
  } while (0)
