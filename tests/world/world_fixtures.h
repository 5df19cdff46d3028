// Shared helpers for the world tests: the shipped kitchen domain and
// scenario, loaded once per call, and short ways to name facts and actions.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "world/action.h"
#include "world/goal.h"
#include "world/pddl.h"
#include "world/scenario.h"

namespace apprentice::testing {

inline std::filesystem::path source_path(std::string_view relative) {
  return std::filesystem::path(APPRENTICE_SOURCE_DIR) / relative;
}

inline std::filesystem::path kitchen_domain_path() { return source_path("data/domains/kitchen.pddl"); }
inline std::filesystem::path tidy_kitchen_path() { return source_path("data/scenarios/tidy-kitchen.yaml"); }

// Loads a shipped scenario; fails the test (and aborts it) if it cannot.
inline Scenario load_or_die(const std::filesystem::path& path) {
  auto scenario = load_scenario(path);
  if (!scenario) {
    ADD_FAILURE() << scenario.error().describe();
    std::abort();
  }
  return std::move(*scenario);
}

// "(open fridge1)" -> the Action, checked.
inline Action action(const World& world, std::string_view text) {
  auto parsed = parse_action(*world.domain, *world.universe, text);
  EXPECT_TRUE(parsed.has_value()) << (parsed ? "" : parsed.error().describe());
  return parsed ? *parsed : Action();
}

// "(closed fridge1)" -> the Fact, via the goal reader.
inline Fact fact(const World& world, std::string_view text) {
  auto goal = parse_goal(*world.domain, *world.universe, text);
  EXPECT_TRUE(goal.has_value()) << (goal ? "" : goal.error().describe());
  if (!goal || goal->literals.size() != 1) return Fact();
  return goal->literals[0].fact;
}

inline ObjectId object(const World& world, std::string_view id) {
  auto found = world.universe->find(id);
  EXPECT_TRUE(found.has_value()) << "no object " << id;
  return found.value_or(0);
}

}  // namespace apprentice::testing
