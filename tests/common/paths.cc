#include "common/paths.h"

#include <cstdlib>

namespace apprentice::testing {

namespace fs = std::filesystem;

fs::path source_path(std::string_view relative) { return fs::path(APPRENTICE_SOURCE_DIR) / relative; }

fs::path shared_path(std::string_view relative) { return fs::path(APPRENTICE_SHARED_DIR) / relative; }

fs::path scenario_path(std::string_view name) {
  return source_path("data/scenarios/" + std::string(name) + ".yaml");
}

fs::path corpus_path() { return shared_path("data/stars-tidy-kitchen/goal_responses.jsonl"); }

fs::path built_vectors_path() { return fs::path(APPRENTICE_BUILD_DIR) / "vectors" / "glove-6b-100d.vectors"; }

bool have_corpus() { return fs::exists(corpus_path()); }

bool in_ci() {
  const char* ci = std::getenv("CI");
  if (ci == nullptr) return false;
  std::string_view value(ci);
  return value == "true" || value == "1" || value == "TRUE" || value == "True";
}

}  // namespace apprentice::testing
