// Helpers for the language tests: the shipped 35-object kitchen, one
// Grounder with WordNet for the whole binary. Paths (the shared STARS data
// too) and scenario loading come from tests/common.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "common/paths.h"
#include "common/scenarios.h"
#include "language/grounding.h"

namespace apprentice::language::testing {

using apprentice::testing::shared_path;
using apprentice::testing::source_path;

// The scenario, loaded once; a failure to load aborts the binary, since
// every test below needs it.
inline const Scenario& kitchen35() {
  static const Scenario scenario = apprentice::testing::shipped_scenario("tidy-kitchen-35");
  return scenario;
}

inline const World& world35() { return kitchen35().world; }

// The paper's 30-object kitchen, the world of `apprentice teach`.
inline const Scenario& kitchen30() {
  static const Scenario scenario = apprentice::testing::shipped_scenario("tidy-kitchen");
  return scenario;
}

// WordNet decisions are logged at info; the tests keep stderr quiet.
inline const Grounder& grounder() {
  static const Grounder instance = [] {
    spdlog::set_level(spdlog::level::warn);
    return Grounder(Lexicon::open_default());
  }();
  return instance;
}

inline ObjectId id(std::string_view name) {
  auto found = world35().universe->find(name);
  if (!found) {
    ADD_FAILURE() << "no object " << name;
    return 0;
  }
  return *found;
}

// What a sentence grounds to, as format_grounding writes it.
inline std::string meaning(std::string_view sentence, std::optional<ObjectId> object = std::nullopt) {
  return format_grounding(world35(), grounder().interpret(sentence, world35(), object).result);
}

}  // namespace apprentice::language::testing
