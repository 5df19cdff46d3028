// Helpers for the world tests: the shipped kitchen domain and scenario, and
// facts by their PDDL. Paths, scenarios, objects and actions by name come
// from tests/common.
#pragma once

#include <filesystem>
#include <string_view>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/world_helpers.h"
#include "world/pddl.h"

namespace apprentice::testing {

inline std::filesystem::path kitchen_domain_path() { return source_path("data/domains/kitchen.pddl"); }
inline std::filesystem::path tidy_kitchen_path() { return source_path("data/scenarios/tidy-kitchen.yaml"); }

// "(closed fridge1)" -> the Fact, via the goal reader.
inline Fact fact(const World& world, std::string_view text) {
  auto goal = parse_goal(*world.domain, *world.universe, text);
  EXPECT_TRUE(goal.has_value()) << (goal ? "" : goal.error().describe());
  if (!goal || goal->literals.size() != 1) return Fact();
  return goal->literals[0].fact;
}

}  // namespace apprentice::testing
