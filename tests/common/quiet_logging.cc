// The library logs what the agent does (groundings, LLM failures) through
// spdlog; in the tests that is noise unless asked for: set
// APPRENTICE_TEST_LOG=1 to see it on stderr. Linked into every test binary
// (an object library, so that the registration is not dropped by the linker).
#include <cstdlib>

#include <gtest/gtest.h>

#include "util/log.h"

namespace {

class QuietLogging : public ::testing::Environment {
 public:
  void SetUp() override {
    const char* wanted = std::getenv("APPRENTICE_TEST_LOG");
    apprentice::configure_logging(wanted != nullptr && *wanted != '\0' && *wanted != '0' ? apprentice::LogLevel::kInfo
                                                                                        : apprentice::LogLevel::kQuiet);
  }
};

[[maybe_unused]] ::testing::Environment* const kQuietLogging = ::testing::AddGlobalTestEnvironment(new QuietLogging);

}  // namespace
