// A problem written with write_problem and read back with parse_problem
// plans to the same plan length, with relevance pruning on and off.
#include <gtest/gtest.h>

#include <string_view>

#include "search_fixtures.h"
#include "world/pddl.h"

namespace apprentice {
namespace {

using testing::goal_or_die;

TEST(PddlRoundTrip, ReReadProblemHasPlansOfTheSameLength) {
  Scenario scenario = testing::tidy_kitchen();
  const World& world = scenario.world;
  for (const char* text : {"(and (in ketchup1 fridge1) (closed fridge1))",
                           "(and (in mug2 cupboard1) (closed cupboard1))", "(on ketchup1 counter1)"}) {
    Goal goal = goal_or_die(world, text);
    PlanResult original = find_plan(*world.domain, *world.universe, world.state, goal, {});
    ASSERT_EQ(original.status, SearchStatus::kSolved) << text;

    auto domain = parse_domain(write_domain(*world.domain), "domain.pddl");
    ASSERT_TRUE(domain.has_value()) << domain.error().describe();
    auto problem = parse_problem(
        *domain, write_problem(scenario.name, *world.domain, *world.universe, world.state, goal), "problem.pddl");
    ASSERT_TRUE(problem.has_value()) << problem.error().describe();
    // Without pruning only for the short goal: unpruned search of the whole
    // kitchen is slow under the sanitizers, and pruning is checked elsewhere.
    const bool short_goal = std::string_view(text) == "(on ketchup1 counter1)";
    for (bool prune : {true, false}) {
      if (!prune && !short_goal) continue;
      SearchOptions options;
      options.prune_irrelevant = prune;
      PlanResult reread = find_plan(*domain, problem->universe, problem->init, problem->goal, options);
      ASSERT_EQ(reread.status, SearchStatus::kSolved) << text << (prune ? " pruned" : " unpruned");
      EXPECT_EQ(reread.plan.size(), original.plan.size()) << text;
      // Replaying the re-read plan by name in the original world reaches the goal.
      World replay_world = world;
      Simulator sim(replay_world);
      for (const Action& a : reread.plan) {
        auto action = parse_action(*world.domain, *world.universe, format_action(*domain, problem->universe, a));
        ASSERT_TRUE(action.has_value());
        ASSERT_TRUE(sim.execute(*action).has_value());
      }
      EXPECT_TRUE(goal.satisfied_by(sim.state())) << text;
    }
  }
}

}  // namespace
}  // namespace apprentice
