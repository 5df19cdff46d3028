// Properties of greedy best-first search on generated small problems, in
// the kitchen and in the kitchen where dishes stack (objects interact):
//   1. every plan found replays in the Simulator and reaches the goal;
//   2. it finds a plan exactly when one exists (checked by an independent
//      breadth-first search over every object, without pruning), so
//      relevance pruning never loses a plan and exhaustion is a proof;
//   3. its plans are at most 10% longer than the shortest.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "search/greedy_best_first.h"
#include "search_generators.h"

namespace apprentice {
namespace {

using testing::Problem;
using testing::shortest_plan_length;

PlanResult greedy(const Problem& problem, bool prune = true) {
  SearchOptions options;
  options.prune_irrelevant = prune;
  return find_greedy_plan(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal, options);
}

// Properties 1-3 for one problem.
void check_against_reference(const Problem& problem) {
  const std::optional<int> shortest =
      shortest_plan_length(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal);
  RC_CLASSIFY(!shortest.has_value(), "unreachable");
  RC_CLASSIFY(shortest.has_value() && *shortest >= 6, "6 or more steps");
  for (bool prune : {true, false}) {
    const PlanResult result = greedy(problem, prune);
    RC_ASSERT(result.status != SearchStatus::kInProgress);
    RC_ASSERT(result.status != SearchStatus::kBudgetExhausted);
    RC_ASSERT((result.status == SearchStatus::kSolved) == shortest.has_value());
    if (!shortest) continue;
    Simulator sim(problem.world);
    for (const Action& action : result.plan) RC_ASSERT(sim.execute(action).has_value());
    RC_ASSERT(problem.goal.satisfied_by(sim.state()));
    const auto length = static_cast<int>(result.plan.size());
    RC_ASSERT(length >= *shortest);
    RC_ASSERT(length * 10 <= *shortest * 11);
  }
}

RC_GTEST_PROP(GreedyProperties, KitchenPlansReplayExistExactlyWhenPlansDoAndAreNearShortest, ()) {
  const testing::WorldSpec spec = *testing::small_worlds();
  RC_LOG() << spec << "\n";
  check_against_reference(testing::build_problem(spec));
}

RC_GTEST_PROP(GreedyProperties, StackingPlansReplayExistExactlyWhenPlansDoAndAreNearShortest, ()) {
  const testing::StackWorldSpec spec = *testing::small_stack_worlds();
  RC_LOG() << spec << "\n";
  check_against_reference(testing::build_stack_problem(spec));
}

RC_GTEST_PROP(GreedyProperties, NodeBudgetIsNeverExceeded, ()) {
  const testing::StackWorldSpec spec = *testing::small_stack_worlds();
  const auto budget = *rc::gen::inRange<std::uint64_t>(1, 50);
  RC_LOG() << spec << "; budget " << budget << "\n";
  const Problem problem = testing::build_stack_problem(spec);
  SearchOptions options;
  options.max_nodes = budget;
  const PlanResult limited =
      find_greedy_plan(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal, options);
  RC_ASSERT(limited.statistics.nodes_expanded <= budget);
  const PlanResult free = greedy(problem);
  if (limited.status == SearchStatus::kBudgetExhausted) {
    RC_ASSERT(limited.statistics.nodes_expanded == budget);
    RC_ASSERT(free.statistics.nodes_expanded >= budget);
  } else {
    RC_ASSERT(limited.status == free.status);
    RC_ASSERT(limited.plan == free.plan);
  }
}

}  // namespace
}  // namespace apprentice
