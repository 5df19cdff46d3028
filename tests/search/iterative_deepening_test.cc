// Iterative deepening on the kitchen: shortest plans, exhaustion as an
// outcome, the stepper and its budgets, determinism, and independence from
// irrelevant objects.
#include "search/iterative_deepening.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "search/relevance.h"
#include "search_fixtures.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using testing::goal_or_die;
using testing::plan_text;
using testing::shortest_plan_length;

constexpr const char* kKetchupGoal = "(and (in ketchup1 fridge1) (closed fridge1))";

class KitchenSearch : public ::testing::Test {
 protected:
  void SetUp() override {
    scenario_ = testing::tidy_kitchen();
    world_ = scenario_.world;
  }
  PlanResult plan(std::string_view goal, SearchOptions options = {}) const {
    return find_plan(*world_.domain, *world_.universe, world_.state, goal_or_die(world_, goal), options);
  }
  // Replays a plan in the simulator; returns the final state.
  State replay(const std::vector<Action>& plan) const {
    Simulator sim(world_);
    for (const Action& a : plan) {
      Status status = sim.execute(a);
      EXPECT_TRUE(status.has_value()) << status.error().describe();
    }
    return sim.state();
  }

  Scenario scenario_;
  World world_;
};

TEST_F(KitchenSearch, KetchupPlanIsOpenPickUpPutClose) {
  PlanResult result = plan(kKetchupGoal);
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_THAT(plan_text(world_, result.plan), ElementsAre("(open fridge1)", "(pick-up ketchup1 table1)",
                                                          "(put-in ketchup1 fridge1)", "(close fridge1)"));
  EXPECT_TRUE(goal_or_die(world_, kKetchupGoal).satisfied_by(replay(result.plan)));
  EXPECT_EQ(result.statistics.depth_limit_reached, 4);
  EXPECT_GT(result.statistics.nodes_expanded, 0u);
  EXPECT_GE(result.statistics.nodes_generated, result.statistics.nodes_expanded);
  EXPECT_EQ(result.statistics.relevant_objects, 12u);  // ketchup1 and the 11 places
  EXPECT_GE(result.statistics.elapsed_ms, 0.0);
}

TEST_F(KitchenSearch, DepthTwoIsExhaustedNotAnError) {
  SearchOptions options;
  options.max_depth = 2;
  PlanResult result = plan(kKetchupGoal, options);
  EXPECT_EQ(result.status, SearchStatus::kExhausted);
  EXPECT_TRUE(result.plan.empty());
  EXPECT_EQ(result.statistics.depth_limit_reached, 2);
  options.max_depth = 3;
  EXPECT_EQ(plan(kKetchupGoal, options).status, SearchStatus::kExhausted);
  options.max_depth = 4;
  EXPECT_EQ(plan(kKetchupGoal, options).status, SearchStatus::kSolved);
}

TEST_F(KitchenSearch, GoalAlreadyTrueGivesTheEmptyPlan) {
  PlanResult result = plan("(and (on ketchup1 table1) (closed fridge1))");
  EXPECT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(result.plan.empty());
  EXPECT_EQ(result.statistics.nodes_expanded, 0u);
  SearchOptions zero;
  zero.max_depth = 0;
  EXPECT_EQ(plan("(on ketchup1 table1)", zero).status, SearchStatus::kSolved);
  EXPECT_EQ(plan(kKetchupGoal, zero).status, SearchStatus::kExhausted);
}

TEST_F(KitchenSearch, MugFromTheDishRackUsesPickUpFrom) {
  PlanResult result = plan("(and (in mug2 cupboard1) (closed cupboard1))");
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_THAT(plan_text(world_, result.plan), ElementsAre("(open cupboard1)", "(pick-up-from mug2 dish-rack1)",
                                                          "(put-in mug2 cupboard1)", "(close cupboard1)"));
  PlanResult open_ok = plan("(in mug2 cupboard1)");
  ASSERT_EQ(open_ok.status, SearchStatus::kSolved);
  EXPECT_EQ(open_ok.plan.size(), 3u);
}

TEST_F(KitchenSearch, ShortPlansAreShortest) {
  EXPECT_EQ(plan("(on ketchup1 counter1)").plan.size(), 2u);
  EXPECT_EQ(plan("(in ketchup1 sink1)").plan.size(), 2u);
  EXPECT_EQ(plan("(not (closed fridge1))").plan.size(), 1u);
  EXPECT_EQ(plan("(holding milk1)").plan.size(), 1u);
  // Reaching into a closed receptacle and leaving it closed.
  SearchOptions deep;
  deep.max_depth = 6;
  PlanResult two = plan("(and (in ketchup1 fridge1) (in milk1 fridge1) (closed fridge1))", deep);
  ASSERT_EQ(two.status, SearchStatus::kSolved);
  EXPECT_EQ(two.plan.size(), 6u);
  EXPECT_EQ(plan_text(world_, two.plan).front(), "(open fridge1)");
  EXPECT_EQ(plan_text(world_, two.plan).back(), "(close fridge1)");
}

TEST_F(KitchenSearch, UnreachableGoalIsExhaustedAtTheDepthLimit) {
  SearchOptions options;
  options.max_depth = 3;
  PlanResult result = plan("(closed garbage1)", options);
  EXPECT_EQ(result.status, SearchStatus::kExhausted);
  EXPECT_EQ(result.statistics.depth_limit_reached, 3);
}

TEST_F(KitchenSearch, HeldItemMustBePutDownFirst) {
  Simulator sim(world_);
  ASSERT_TRUE(sim.execute(*parse_action(*world_.domain, *world_.universe, "(pick-up milk1 table1)")).has_value());
  const State holding = sim.state();
  SearchOptions options;
  options.max_depth = 6;
  Goal goal = goal_or_die(world_, kKetchupGoal);
  PlanResult result = find_plan(*world_.domain, *world_.universe, holding, goal, options);
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  // Put the milk down (anywhere), then the four steps.
  EXPECT_EQ(result.plan.size(), 5u);
  auto text = plan_text(world_, result.plan);
  EXPECT_THAT(text.front(), ::testing::StartsWith("(put-"));
  EXPECT_THAT(text.front(), ::testing::HasSubstr("milk1"));
  EXPECT_EQ(result.statistics.relevant_objects, 13u);  // + milk1, in hand
}

TEST_F(KitchenSearch, SteppingOneNodeAtATimeMatchesRun) {
  Goal goal = goal_or_die(world_, kKetchupGoal);
  IterativeDeepeningSearch whole(*world_.domain, *world_.universe, world_.state, goal, {});
  ASSERT_EQ(whole.run(), SearchStatus::kSolved);

  IterativeDeepeningSearch stepped(*world_.domain, *world_.universe, world_.state, goal, {});
  std::uint64_t calls = 0;
  std::uint64_t last_expanded = 0;
  while (stepped.step(1) == SearchStatus::kInProgress) {
    ++calls;
    // Each call expands at most one node.
    EXPECT_LE(stepped.statistics().nodes_expanded, last_expanded + 1);
    last_expanded = stepped.statistics().nodes_expanded;
    ASSERT_LT(calls, 1000000u);
  }
  EXPECT_GT(calls, 1u);
  EXPECT_EQ(stepped.status(), SearchStatus::kSolved);
  EXPECT_EQ(stepped.plan(), whole.plan());
  EXPECT_EQ(stepped.statistics().nodes_expanded, whole.statistics().nodes_expanded);
  EXPECT_EQ(stepped.statistics().nodes_generated, whole.statistics().nodes_generated);
  EXPECT_EQ(stepped.statistics().depth_limit_reached, whole.statistics().depth_limit_reached);
  EXPECT_EQ(stepped.statistics().ground_actions, whole.statistics().ground_actions);
}

TEST_F(KitchenSearch, SteppingWithUnevenBudgetsMatchesRunWhenExhausted) {
  Goal goal = goal_or_die(world_, kKetchupGoal);
  SearchOptions options;
  options.max_depth = 3;
  IterativeDeepeningSearch whole(*world_.domain, *world_.universe, world_.state, goal, options);
  ASSERT_EQ(whole.run(), SearchStatus::kExhausted);
  IterativeDeepeningSearch stepped(*world_.domain, *world_.universe, world_.state, goal, options);
  std::uint64_t budget = 1;
  while (stepped.step(budget) == SearchStatus::kInProgress) budget = budget % 7 + 1;
  EXPECT_EQ(stepped.status(), SearchStatus::kExhausted);
  EXPECT_EQ(stepped.statistics().nodes_expanded, whole.statistics().nodes_expanded);
  EXPECT_EQ(stepped.statistics().nodes_generated, whole.statistics().nodes_generated);
}

TEST_F(KitchenSearch, FinalStatusIsSticky) {
  Goal goal = goal_or_die(world_, kKetchupGoal);
  IterativeDeepeningSearch search(*world_.domain, *world_.universe, world_.state, goal, {});
  ASSERT_EQ(search.run(), SearchStatus::kSolved);
  SearchStatistics before = search.statistics();
  std::vector<Action> plan = search.plan();
  EXPECT_EQ(search.step(100), SearchStatus::kSolved);
  EXPECT_EQ(search.run(), SearchStatus::kSolved);
  EXPECT_EQ(search.plan(), plan);
  EXPECT_EQ(search.statistics().nodes_expanded, before.nodes_expanded);
  EXPECT_EQ(search.statistics().nodes_generated, before.nodes_generated);
}

TEST_F(KitchenSearch, StepZeroMakesNoProgress) {
  Goal goal = goal_or_die(world_, kKetchupGoal);
  IterativeDeepeningSearch search(*world_.domain, *world_.universe, world_.state, goal, {});
  EXPECT_EQ(search.status(), SearchStatus::kInProgress);
  EXPECT_EQ(search.step(0), SearchStatus::kInProgress);
  EXPECT_EQ(search.statistics().nodes_expanded, 0u);
  EXPECT_EQ(search.run(), SearchStatus::kSolved);
}

TEST_F(KitchenSearch, NodeBudgetStopsTheSearch) {
  SearchOptions options;
  options.max_nodes = 10;
  PlanResult result = plan(kKetchupGoal, options);
  EXPECT_EQ(result.status, SearchStatus::kBudgetExhausted);
  EXPECT_TRUE(result.plan.empty());
  EXPECT_EQ(result.statistics.nodes_expanded, 10u);
  // A budget large enough changes nothing.
  PlanResult unlimited = plan(kKetchupGoal);
  options.max_nodes = unlimited.statistics.nodes_expanded;
  PlanResult enough = plan(kKetchupGoal, options);
  EXPECT_EQ(enough.status, SearchStatus::kSolved);
  EXPECT_EQ(enough.plan, unlimited.plan);
  options.max_nodes = unlimited.statistics.nodes_expanded - 1;
  EXPECT_EQ(plan(kKetchupGoal, options).status, SearchStatus::kBudgetExhausted);
}

TEST_F(KitchenSearch, SpentTimeBudgetStopsTheSearch) {
  // A zero time budget is spent before the first expansion; this does not
  // depend on how fast the machine is.
  SearchOptions options;
  options.max_time = std::chrono::milliseconds(0);
  PlanResult result = plan(kKetchupGoal, options);
  EXPECT_EQ(result.status, SearchStatus::kBudgetExhausted);
  EXPECT_EQ(result.statistics.nodes_expanded, 0u);
  // A goal that needs no search is still solved.
  EXPECT_EQ(plan("(on ketchup1 table1)", options).status, SearchStatus::kSolved);
}

TEST_F(KitchenSearch, IsDeterministic) {
  for (const char* goal : {kKetchupGoal, "(and (in mug2 cupboard1) (closed cupboard1))", "(in soda-can2 recycling-bin1)"}) {
    PlanResult a = plan(goal);
    PlanResult b = plan(goal);
    EXPECT_EQ(a.status, b.status) << goal;
    EXPECT_EQ(a.plan, b.plan) << goal;
    EXPECT_EQ(a.statistics.nodes_expanded, b.statistics.nodes_expanded) << goal;
    EXPECT_EQ(a.statistics.nodes_generated, b.statistics.nodes_generated) << goal;
    // And the same for a freshly loaded copy of the scenario.
    Scenario again = testing::tidy_kitchen();
    PlanResult c = find_plan(*again.world.domain, *again.world.universe, again.world.state,
                             goal_or_die(again.world, goal), {});
    EXPECT_EQ(c.plan, a.plan) << goal;
    EXPECT_EQ(c.statistics.nodes_expanded, a.statistics.nodes_expanded) << goal;
  }
}

TEST_F(KitchenSearch, PruningOffFindsPlansOfTheSameLength) {
  SearchOptions off;
  off.prune_irrelevant = false;
  // Goals of up to three steps: unpruned search of the whole kitchen is
  // slow under the sanitizers (the benchmark covers the four-step goal).
  for (const char* goal : {"(in mug2 cupboard1)", "(on ketchup1 counter1)", "(not (closed drawer1))"}) {
    PlanResult pruned = plan(goal);
    PlanResult full = plan(goal, off);
    ASSERT_EQ(pruned.status, SearchStatus::kSolved) << goal;
    ASSERT_EQ(full.status, SearchStatus::kSolved) << goal;
    EXPECT_EQ(pruned.plan.size(), full.plan.size()) << goal;
    EXPECT_LE(pruned.statistics.ground_actions, full.statistics.ground_actions) << goal;
    EXPECT_EQ(full.statistics.relevant_objects, world_.universe->size()) << goal;
  }
}

TEST_F(KitchenSearch, PlansAgreeWithBreadthFirstSearchOnTheKitchen) {
  // The reference search runs over a kitchen cut down to a few objects so
  // that exhaustive search stays small.
  std::vector<ObjectId> keep;
  for (const char* id : {"table1", "counter1", "dish-rack1", "sink1", "fridge1", "cupboard1", "ketchup1", "mug2"})
    keep.push_back(*world_.universe->find(id));
  std::sort(keep.begin(), keep.end());
  State small = project_state(world_.state, keep);
  for (const char* text : {kKetchupGoal, "(and (in mug2 cupboard1) (closed cupboard1))", "(on mug2 table1)",
                           "(and (in ketchup1 cupboard1) (in mug2 fridge1))"}) {
    Goal goal = goal_or_die(world_, text);
    SearchOptions options;
    options.max_depth = 8;
    PlanResult result = find_plan(*world_.domain, *world_.universe, small, goal, options);
    ASSERT_EQ(result.status, SearchStatus::kSolved) << text;
    auto reference = shortest_plan_length(*world_.domain, *world_.universe, small, goal);
    ASSERT_TRUE(reference.has_value()) << text;
    EXPECT_EQ(static_cast<int>(result.plan.size()), *reference) << text;
  }
}

// A kitchen with many extra items costs the same search as without them:
// the same relevant objects, ground actions, nodes and plan.
TEST(SearchScaling, IrrelevantObjectsDoNotChangeTheSearch) {
  Scenario base = testing::tidy_kitchen();
  const World& world = base.world;
  Goal goal = goal_or_die(world, kKetchupGoal);
  PlanResult reference = find_plan(*world.domain, *world.universe, world.state, goal, {});

  Universe universe = *world.universe;
  std::vector<Fact> facts(world.state.facts().begin(), world.state.facts().end());
  std::vector<ObjectId> places = universe.of_kind(ObjectKind::kSurface);
  for (ObjectId r : universe.of_kind(ObjectKind::kReceptacle)) places.push_back(r);
  for (int i = 0; i < 2000; ++i) {
    ObjectId id = universe.add(ObjectInfo{"extra" + std::to_string(i), "extra", ObjectKind::kItem,
                                          *world.domain->find_type("item"), {}});
    ObjectId place = places[static_cast<std::size_t>(i) % places.size()];
    facts.push_back(Fact(world.vocabulary.grabbable, {id}));
    bool surface = universe.info(place).kind == ObjectKind::kSurface;
    facts.push_back(Fact(surface ? world.vocabulary.on : world.vocabulary.in, {id, place}));
  }
  State big(std::move(facts));
  PlanResult result = find_plan(*world.domain, universe, big, goal, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_EQ(result.plan, reference.plan);
  EXPECT_EQ(result.statistics.relevant_objects, reference.statistics.relevant_objects);
  EXPECT_EQ(result.statistics.ground_actions, reference.statistics.ground_actions);
  EXPECT_EQ(result.statistics.nodes_expanded, reference.statistics.nodes_expanded);
  EXPECT_EQ(result.statistics.nodes_generated, reference.statistics.nodes_generated);
}

TEST(SearchStatusNames, AreStable) {
  EXPECT_STREQ(to_string(SearchStatus::kInProgress), "in-progress");
  EXPECT_STREQ(to_string(SearchStatus::kSolved), "solved");
  EXPECT_STREQ(to_string(SearchStatus::kExhausted), "exhausted");
  EXPECT_STREQ(to_string(SearchStatus::kBudgetExhausted), "budget-exhausted");
}

}  // namespace
}  // namespace apprentice
