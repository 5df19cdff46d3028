// Greedy best-first search on the kitchen: whole tasks planned and
// replayed, exhaustion and budgets as outcomes, the stepper, progress
// reports, determinism, and the parts it is built from (the ground task,
// the state registry, the successor generator, the FF heuristic).
#include "search/greedy_best_first.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "search/ff_heuristic.h"
#include "search/ground_task.h"
#include "search/relevance.h"
#include "search/state_registry.h"
#include "search/successor_generator.h"
#include "search_fixtures.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using testing::goal_or_die;
using testing::plan_reaches;
using testing::plan_text;

constexpr const char* kKetchupGoal = "(and (in ketchup1 fridge1) (closed fridge1))";

class GreedyKitchen : public ::testing::Test {
 protected:
  void SetUp() override {
    scenario_ = testing::tidy_kitchen();
    world_ = scenario_.world;
  }
  PlanResult plan(const Goal& goal, SearchOptions options = {}) const {
    return find_greedy_plan(*world_.domain, *world_.universe, world_.state, goal, options);
  }
  PlanResult plan(std::string_view goal, SearchOptions options = {}) const {
    return plan(goal_or_die(world_, goal), std::move(options));
  }
  Scenario scenario_;
  World world_;
};

TEST_F(GreedyKitchen, KetchupPlanIsOpenPickUpPutClose) {
  PlanResult result = plan(kKetchupGoal);
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_THAT(plan_text(world_, result.plan), ElementsAre("(open fridge1)", "(pick-up ketchup1 table1)",
                                                          "(put-in ketchup1 fridge1)", "(close fridge1)"));
  EXPECT_EQ(result.statistics.relevant_objects, 12u);  // ketchup1 and the 11 places
  EXPECT_EQ(result.statistics.initial_heuristic, 3);   // open, pick up, put in: the relaxed plan needs no close
  EXPECT_EQ(result.statistics.best_heuristic, 1);      // the goal state itself is recognized, not evaluated
  EXPECT_GT(result.statistics.nodes_expanded, 0u);
  EXPECT_EQ(result.statistics.nodes_evaluated, result.statistics.nodes_expanded);
}

TEST_F(GreedyKitchen, PlansTheWholeTidyKitchenTask) {
  const Goal goal(scenario_.goal_assertions());
  ASSERT_EQ(goal.literals.size(), 35u);
  PlanResult result = plan(goal);
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, result.plan, goal));
  // 70 is optimal: each of the 30 items must be picked up and put down,
  // and each of the 5 receptacles with doors receives an item, so it must
  // be opened and closed again; the plan found reaches that bound.
  EXPECT_GE(result.plan.size(), 70u);
  EXPECT_LE(result.plan.size(), 77u);
}

TEST_F(GreedyKitchen, PlansTheWholeTidyKitchen35Task) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen-35.yaml"));
  const Goal goal(scenario.goal_assertions());
  PlanResult result =
      find_greedy_plan(*scenario.world.domain, *scenario.world.universe, scenario.world.state, goal, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(scenario.world, result.plan, goal));
}

TEST_F(GreedyKitchen, AGoalThatHoldsNeedsNoSteps) {
  PlanResult result = plan("(on ketchup1 table1)");
  EXPECT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(result.plan.empty());
  EXPECT_EQ(result.statistics.nodes_expanded, 0u);
}

TEST_F(GreedyKitchen, AnUnreachableGoalIsExhaustedNotAnError) {
  // The garbage has no lid: nothing can close it.
  PlanResult lidless = plan("(closed garbage1)");
  EXPECT_EQ(lidless.status, SearchStatus::kExhausted);
  EXPECT_EQ(lidless.statistics.initial_heuristic, FfHeuristic::kDeadEnd);
  // A static fact that does not hold.
  PlanResult affordance = plan("(openable sink1)");
  EXPECT_EQ(affordance.status, SearchStatus::kExhausted);
}

TEST_F(GreedyKitchen, ExhaustsTheStateSpaceWhenTheRelaxationCannotTell) {
  // Both placements are reachable on their own, so the relaxed plan exists,
  // but one item cannot be in two places: only search proves it impossible.
  PlanResult result = plan("(and (in ketchup1 fridge1) (in ketchup1 pantry1))");
  EXPECT_EQ(result.status, SearchStatus::kExhausted);
  EXPECT_GT(result.statistics.nodes_expanded, 1u);
  EXPECT_EQ(result.statistics.states_registered, result.statistics.nodes_expanded);
}

TEST_F(GreedyKitchen, NodeLimitStopsWithBudgetExhausted) {
  SearchOptions options;
  options.max_nodes = 3;
  PlanResult result = plan(Goal(scenario_.goal_assertions()), options);
  EXPECT_EQ(result.status, SearchStatus::kBudgetExhausted);
  EXPECT_EQ(result.statistics.nodes_expanded, 3u);
}

TEST_F(GreedyKitchen, TimeLimitStopsWithBudgetExhausted) {
  SearchOptions options;
  options.max_time = std::chrono::milliseconds(0);
  PlanResult result = plan(Goal(scenario_.goal_assertions()), options);
  EXPECT_EQ(result.status, SearchStatus::kBudgetExhausted);
  EXPECT_EQ(result.statistics.nodes_expanded, 1u);  // only the initial state, evaluated before the first step
}

TEST_F(GreedyKitchen, ReportsProgressWithNodesAndTheBestHeuristicValue) {
  std::vector<SearchProgress> reports;
  SearchOptions options;
  options.progress = [&](const SearchProgress& p) { reports.push_back(p); };
  options.progress_interval = std::chrono::milliseconds(0);
  PlanResult result = plan(Goal(scenario_.goal_assertions()), options);
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  ASSERT_FALSE(reports.empty());
  for (std::size_t i = 1; i < reports.size(); ++i) {
    EXPECT_GE(reports[i].nodes_expanded, reports[i - 1].nodes_expanded);
    EXPECT_LE(reports[i].best_heuristic, reports[i - 1].best_heuristic);
  }
  EXPECT_GE(reports.front().best_heuristic, result.statistics.best_heuristic);
  EXPECT_LE(reports.back().nodes_expanded, result.statistics.nodes_expanded);
  // Without a callback nothing is reported, and the default interval is a second.
  EXPECT_EQ(SearchOptions{}.progress_interval, std::chrono::seconds(1));
}

TEST_F(GreedyKitchen, SteppingInChunksMatchesRun) {
  const Goal goal(scenario_.goal_assertions());
  GreedyBestFirstSearch whole(*world_.domain, *world_.universe, world_.state, goal, {});
  whole.run();
  GreedyBestFirstSearch stepped(*world_.domain, *world_.universe, world_.state, goal, {});
  while (stepped.step(7) == SearchStatus::kInProgress) {
  }
  EXPECT_EQ(stepped.status(), whole.status());
  EXPECT_EQ(stepped.plan(), whole.plan());
  EXPECT_EQ(stepped.statistics().nodes_expanded, whole.statistics().nodes_expanded);
  EXPECT_EQ(stepped.step(100), whole.status());  // a final status stays
}

TEST_F(GreedyKitchen, IsDeterministic) {
  const Goal goal(scenario_.goal_assertions());
  PlanResult a = plan(goal), b = plan(goal);
  EXPECT_EQ(a.plan, b.plan);
  EXPECT_EQ(a.statistics.nodes_expanded, b.statistics.nodes_expanded);
  EXPECT_EQ(a.statistics.nodes_generated, b.statistics.nodes_generated);
}

TEST_F(GreedyKitchen, PlanImprovementOnlyRemovesSteps) {
  const Goal goal(scenario_.goal_assertions());
  SearchOptions raw;
  raw.improve_plan = false;
  PlanResult unimproved = plan(goal, raw);
  PlanResult improved = plan(goal);
  ASSERT_EQ(unimproved.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, unimproved.plan, goal));
  EXPECT_EQ(unimproved.statistics.steps_removed, 0u);
  EXPECT_EQ(improved.plan.size() + improved.statistics.steps_removed, unimproved.plan.size());
  // The improved plan is the unimproved one with some steps left out.
  std::size_t j = 0;
  for (const Action& a : unimproved.plan)
    if (j < improved.plan.size() && improved.plan[j] == a) ++j;
  EXPECT_EQ(j, improved.plan.size());
}

TEST_F(GreedyKitchen, PruningChangesNeitherOutcomeNorValidity) {
  const Goal goal = goal_or_die(world_, "(and (in mug2 cupboard1) (closed cupboard1) (on ketchup1 counter1))");
  SearchOptions off;
  off.prune_irrelevant = false;
  PlanResult pruned = plan(goal), full = plan(goal, off);
  ASSERT_EQ(pruned.status, SearchStatus::kSolved);
  ASSERT_EQ(full.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, full.plan, goal));
  EXPECT_EQ(full.statistics.relevant_objects, world_.universe->size());
  EXPECT_LT(pruned.statistics.ground_actions, full.statistics.ground_actions);
  EXPECT_EQ(pruned.plan.size(), full.plan.size());
}

// The parts.

TEST_F(GreedyKitchen, GroundTaskKeepsOnlyDynamicFactsAndReachableActions) {
  const Goal goal = goal_or_die(world_, kKetchupGoal);
  std::vector<ObjectId> objects = relevant_objects(*world_.domain, *world_.universe, world_.state, goal);
  GroundTask task(*world_.domain, *world_.universe, objects, project_state(world_.state, objects), goal);
  for (PropositionId p = 0; p < task.proposition_count(); ++p)
    EXPECT_FALSE(world_.domain->is_static(task.fact(p).predicate));
  // open and close for the 5 doors; ketchup1: pick-up/put-on for 2 surfaces,
  // pick-up-from/put-in for 9 receptacles.
  EXPECT_EQ(task.operator_count(), 5u * 2 + 2 * 2 + 9 * 2);
  EXPECT_FALSE(task.is_goal(task.initial().data()));
  EXPECT_EQ(task.goal_true().size(), 2u);
  EXPECT_TRUE(task.goal_false().empty());
}

TEST_F(GreedyKitchen, SuccessorGeneratorFindsExactlyTheApplicableOperators) {
  const Goal goal(scenario_.goal_assertions());
  std::vector<ObjectId> objects = relevant_objects(*world_.domain, *world_.universe, world_.state, goal);
  GroundTask task(*world_.domain, *world_.universe, objects, project_state(world_.state, objects), goal);
  SuccessorGenerator generator(task);
  // Walk a few states along arbitrary applicable operators; at each, compare
  // with testing every operator.
  std::vector<StateWord> state = task.initial(), next(task.words());
  std::vector<OperatorId> found;
  for (int step = 0; step < 40; ++step) {
    generator.applicable(state.data(), found);
    std::vector<OperatorId> expected;
    for (OperatorId o = 0; o < task.operator_count(); ++o)
      if (task.applicable(state.data(), o)) expected.push_back(o);
    std::vector<OperatorId> sorted = found;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, expected) << "step " << step;
    ASSERT_FALSE(found.empty());
    task.apply(state.data(), found[static_cast<std::size_t>(step * 7) % found.size()], next.data());
    state.swap(next);
  }
}

TEST_F(GreedyKitchen, StateRegistryStoresEachStateOnce) {
  StateRegistry registry(3);
  std::vector<StateWord> a{1, 2, 3}, b{1, 2, 4};
  EXPECT_EQ(registry.insert(a.data()), std::make_pair(StateId{0}, true));
  EXPECT_EQ(registry.insert(b.data()), std::make_pair(StateId{1}, true));
  EXPECT_EQ(registry.insert(a.data()), std::make_pair(StateId{0}, false));
  // Many more states: ids stay dense and lookups exact across table growth.
  for (StateWord i = 0; i < 5000; ++i) {
    std::vector<StateWord> s{i, i * 31, 7};
    auto [id, fresh] = registry.insert(s.data());
    EXPECT_TRUE(fresh);
    EXPECT_EQ(id, i + 2);
  }
  EXPECT_EQ(registry.size(), 5002u);
  EXPECT_EQ(registry.insert(b.data()).first, 1u);
  EXPECT_TRUE(std::equal(b.begin(), b.end(), registry.get(1)));
}

TEST_F(GreedyKitchen, FfHeuristicCountsTheRelaxedPlanAndPrefersItsFirstSteps) {
  const Goal goal = goal_or_die(world_, "(and (in ketchup1 fridge1) (in mug2 cupboard1))");
  std::vector<ObjectId> objects = relevant_objects(*world_.domain, *world_.universe, world_.state, goal);
  GroundTask task(*world_.domain, *world_.universe, objects, project_state(world_.state, objects), goal);
  FfHeuristic h(task);
  std::vector<OperatorId> preferred;
  // open fridge, open cupboard, pick up both, put both: 6.
  EXPECT_EQ(h.evaluate(task.initial().data(), &preferred), 6);
  std::vector<std::string> names;
  for (OperatorId o : preferred) names.push_back(format_action(*world_.domain, *world_.universe, task.op(o).action));
  std::sort(names.begin(), names.end());
  EXPECT_THAT(names, ElementsAre("(open cupboard1)", "(open fridge1)", "(pick-up ketchup1 table1)",
                                 "(pick-up-from mug2 dish-rack1)"));
  for (OperatorId o : preferred) EXPECT_TRUE(task.applicable(task.initial().data(), o));
}

}  // namespace
}  // namespace apprentice
