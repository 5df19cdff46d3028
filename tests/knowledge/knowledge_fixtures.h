// Helpers for the knowledge tests: the shipped scenarios, the ceramic-plate
// episode of the paper's walk-through, learning and matching rules. Paths,
// scratch directories, running the binary and naming objects come from
// tests/common.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"
#include "common/world_helpers.h"
#include "knowledge/learning.h"
#include "knowledge/matcher.h"
#include "knowledge/rule.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace apprentice::testing {

namespace fs = std::filesystem;

inline Scenario tidy_kitchen() { return shipped_scenario("tidy-kitchen"); }
inline Scenario tidy_kitchen_similar() { return shipped_scenario("tidy-kitchen-similar"); }

// The state after executing `actions` in turn from `state` (each checked
// applicable).
inline State after(const World& world, State state, const std::vector<std::string>& actions) {
  for (const std::string& text : actions) {
    Action a = action(world, text);
    EXPECT_TRUE(is_applicable(*world.domain, state, a)) << text;
    state = apply(*world.domain, state, a);
  }
  return state;
}

// An episode from the instructor: each action's source is what the agent
// records for an instructed action.
inline Episode make_episode(const World& world, const State& initial, std::string_view object_id,
                            std::string_view goal_text, std::string_view subtask,
                            const std::vector<std::string>& actions) {
  Episode episode;
  episode.initial = initial;
  for (const std::string& text : actions) {
    episode.actions.push_back(action(world, text));
    episode.sources.push_back("instructor: \"" + text + "\"");
  }
  episode.goal = goal(world, goal_text);
  episode.object_of_interest = object(world, object_id);
  episode.subtask = std::string(subtask);
  episode.object_description =
      std::string(object_id) + " (" + world.universe->info(episode.object_of_interest).category + ")";
  return episode;
}

// The paper's walk-through: the ceramic plate on the table, cleared into
// the dishwasher, which must end closed.
inline constexpr std::string_view kCeramicPlateGoal = "(and (in ceramic-plate1 dishwasher1) (closed dishwasher1))";
inline Episode ceramic_plate_episode(const World& world) {
  return make_episode(world, world.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                      {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)",
                       "(put-in ceramic-plate1 dishwasher1)", "(close dishwasher1)"});
}

inline std::vector<Rule> learn(const World& world, const Episode& episode, Generalization generalization) {
  return learn_policy_rules(*world.domain, *world.universe, episode, generalization);
}

inline RuleMatcher matcher_of(const World& world, const std::vector<Rule>& rules) {
  RuleMatcher matcher;
  for (const Rule& rule : rules) matcher.add(*world.domain, rule);
  return matcher;
}

inline std::vector<std::string> signatures(const World& world, const std::vector<Rule>& rules) {
  std::vector<std::string> out;
  for (const Rule& rule : rules) out.push_back(rule_signature(*world.domain, rule));
  return out;
}

// A test with the tidy kitchen and the path of a store in a scratch
// directory (not yet created).
class KitchenStoreTest : public ::testing::Test {
 protected:
  Scenario scenario_ = tidy_kitchen();
  const World& world_ = scenario_.world;
  const Domain& domain_ = *world_.domain;
  ScratchDir dir_;
  fs::path path_ = dir_ / "knowledge.sqlite";
};

// Runs the apprentice binary with `args` in the test's working directory,
// capturing its output in `dir`.
inline Invocation run_cli(const fs::path& dir, const std::vector<std::string>& args) {
  return run_cli(args, dir, fs::path());
}

}  // namespace apprentice::testing
