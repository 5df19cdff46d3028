// Properties of the planner on generated small kitchens (a few places, some
// with doors open or closed, a few items, maybe one in hand) and generated
// goals (an item in or on a place, maybe a door closed or open, and maybe
// a second item somewhere):
//   1. every plan found replays in the Simulator and reaches the goal;
//   2. no shorter plan exists (checked by an independent breadth-first
//      search over every object, without pruning);
//   3. if the search is exhausted at depth d, no plan of length <= d exists;
// and relevance pruning and stepping change nothing.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "search_generators.h"

namespace apprentice {
namespace {

using testing::build_problem;
using testing::GoalSpec;
using testing::PlaceSpec;
using testing::Problem;
using testing::shortest_plan_length;
using testing::small_worlds;
using testing::WorldSpec;

// Depth limits. Unreachable goals make iterative deepening explore the
// whole tree up to the limit, so properties that may meet them use a
// smaller limit than the optimality property, which first asks the
// reference search whether a plan within its limit exists.
constexpr int kMaxDepth = 6;
constexpr int kOptimalityDepth = 8;

PlanResult plan(const Problem& problem, int max_depth, bool prune = true) {
  SearchOptions options;
  options.max_depth = max_depth;
  options.prune_irrelevant = prune;
  return find_plan(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal, options);
}

std::optional<int> reference_length(const Problem& problem) {
  return shortest_plan_length(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal);
}

RC_GTEST_PROP(SearchProperties, EveryPlanReplaysAndReachesTheGoal, ()) {
  const WorldSpec spec = *small_worlds();
  const int depth = *rc::gen::inRange(0, kMaxDepth + 1);
  RC_LOG() << spec << "; max depth " << depth << "\n";
  const Problem problem = build_problem(spec);
  PlanResult result = plan(problem, depth);
  RC_CLASSIFY(result.status == SearchStatus::kSolved, "solved");
  RC_CLASSIFY(result.status == SearchStatus::kExhausted, "exhausted");
  RC_ASSERT(result.status != SearchStatus::kInProgress);
  RC_ASSERT(result.status != SearchStatus::kBudgetExhausted);
  if (result.status != SearchStatus::kSolved) return;
  RC_ASSERT(static_cast<int>(result.plan.size()) <= depth);
  Simulator sim(problem.world);
  for (const Action& action : result.plan) {
    Status status = sim.execute(action);
    RC_ASSERT(status.has_value());
  }
  RC_ASSERT(problem.goal.satisfied_by(sim.state()));
}

RC_GTEST_PROP(SearchProperties, NoShorterPlanExists, ()) {
  const WorldSpec spec = *small_worlds();
  RC_LOG() << spec << "\n";
  const Problem problem = build_problem(spec);
  std::optional<int> shortest = reference_length(problem);
  RC_PRE(shortest.has_value() && *shortest <= kOptimalityDepth);
  PlanResult result = plan(problem, kOptimalityDepth);
  RC_CLASSIFY(result.plan.empty(), "already true");
  RC_CLASSIFY(result.plan.size() >= 4, "4 or more steps");
  RC_ASSERT(result.status == SearchStatus::kSolved);
  RC_ASSERT(static_cast<int>(result.plan.size()) == *shortest);
}

RC_GTEST_PROP(SearchProperties, ExhaustedMeansNoPlanWithinTheDepth, ()) {
  const WorldSpec spec = *small_worlds();
  const int depth = *rc::gen::inRange(0, kMaxDepth + 1);
  RC_LOG() << spec << "; max depth " << depth << "\n";
  const Problem problem = build_problem(spec);
  PlanResult result = plan(problem, depth);
  std::optional<int> shortest = reference_length(problem);
  RC_CLASSIFY(!shortest.has_value(), "unreachable");
  if (result.status == SearchStatus::kExhausted) {
    RC_ASSERT(!shortest.has_value() || *shortest > depth);
  } else {
    // Conversely, a plan within the depth is always found.
    RC_ASSERT(result.status == SearchStatus::kSolved);
    RC_ASSERT(shortest.has_value() && *shortest <= depth);
  }
}

RC_GTEST_PROP(SearchProperties, PruningChangesNeitherOutcomeNorLength, ()) {
  const WorldSpec spec = *small_worlds();
  const int depth = *rc::gen::inRange(0, kMaxDepth + 1);
  RC_LOG() << spec << "; max depth " << depth << "\n";
  const Problem problem = build_problem(spec);
  PlanResult pruned = plan(problem, depth, true);
  PlanResult full = plan(problem, depth, false);
  RC_ASSERT(pruned.status == full.status);
  RC_ASSERT(pruned.plan.size() == full.plan.size());
  RC_ASSERT(pruned.statistics.ground_actions <= full.statistics.ground_actions);
}

RC_GTEST_PROP(SearchProperties, SteppingInAnyChunksMatchesRun, ()) {
  const WorldSpec spec = *small_worlds();
  const std::vector<int> budgets = *rc::gen::nonEmpty(rc::gen::container<std::vector<int>>(rc::gen::inRange(1, 20)));
  RC_LOG() << spec << "\n";
  const Problem problem = build_problem(spec);
  const World& w = problem.world;
  SearchOptions options;
  options.max_depth = 5;
  IterativeDeepeningSearch whole(*w.domain, *w.universe, w.state, problem.goal, options);
  whole.run();
  IterativeDeepeningSearch stepped(*w.domain, *w.universe, w.state, problem.goal, options);
  std::size_t i = 0;
  while (stepped.step(static_cast<std::uint64_t>(budgets[i % budgets.size()])) == SearchStatus::kInProgress) ++i;
  RC_ASSERT(stepped.status() == whole.status());
  RC_ASSERT(stepped.plan() == whole.plan());
  RC_ASSERT(stepped.statistics().nodes_expanded == whole.statistics().nodes_expanded);
  RC_ASSERT(stepped.statistics().nodes_generated == whole.statistics().nodes_generated);
}

RC_GTEST_PROP(SearchProperties, NodeBudgetIsNeverExceeded, ()) {
  const WorldSpec spec = *small_worlds();
  const auto budget = *rc::gen::inRange<std::uint64_t>(1, 200);
  RC_LOG() << spec << "; budget " << budget << "\n";
  const Problem problem = build_problem(spec);
  SearchOptions options;
  options.max_depth = kMaxDepth;
  options.max_nodes = budget;
  PlanResult limited =
      find_plan(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal, options);
  RC_ASSERT(limited.statistics.nodes_expanded <= budget);
  options.max_nodes.reset();
  PlanResult free =
      find_plan(*problem.world.domain, *problem.world.universe, problem.world.state, problem.goal, options);
  if (limited.status == SearchStatus::kBudgetExhausted) {
    RC_ASSERT(limited.statistics.nodes_expanded == budget);
    RC_ASSERT(free.statistics.nodes_expanded >= budget);
  } else {
    // Within budget the outcome is that of the unlimited search.
    RC_ASSERT(limited.status == free.status);
    RC_ASSERT(limited.plan == free.plan);
  }
}

}  // namespace
}  // namespace apprentice
