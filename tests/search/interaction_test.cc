// Objects that interact (data/domains/kitchen-stacking.pddl): dishes that
// stack, a lid on a pot, a drawer inside a cupboard. Relevance pruning must
// keep what can matter, turn itself off where nothing can be left out, and
// say why; both planners must stay correct.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "search/ff_heuristic.h"
#include "search/greedy_best_first.h"
#include "search/ground_task.h"
#include "search/iterative_deepening.h"
#include "search/relevance.h"
#include "search_fixtures.h"

namespace apprentice {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::goal_or_die;
using testing::plan_reaches;
using testing::plan_text;

std::vector<std::string> names(const Universe& universe, const std::vector<ObjectId>& ids) {
  std::vector<std::string> out;
  for (ObjectId id : ids) out.push_back(universe.name(id));
  return out;
}

std::string all_notes(const std::vector<std::string>& notes) {
  std::string out;
  for (const std::string& n : notes) out += n + "\n";
  return out;
}

class StackedDishes : public ::testing::Test {
 protected:
  void SetUp() override {
    scenario_ = testing::load_or_die(testing::source_path("data/scenarios/stacked-dishes.yaml"));
    world_ = scenario_.world;
  }
  Scenario scenario_;
  World world_;
};

TEST(Interaction, KitchenItemsAreLocalAndTheHandIsOneArm) {
  auto domain = testing::kitchen_domain();
  DomainInteraction interaction = analyze_interaction(*domain);
  ASSERT_EQ(interaction.hands.size(), 1u);
  EXPECT_EQ(interaction.hands[0].empty, domain->predicate("handempty"));
  EXPECT_EQ(interaction.hands[0].holding, domain->predicate("holding"));
  for (std::size_t a = 0; a < domain->actions.size(); ++a) {
    const ActionSchema& schema = domain->actions[a];
    for (std::size_t p = 0; p < schema.parameters.size(); ++p) {
      // Items (?o) are local; places are not, except in open and close.
      const bool item = schema.parameters[p].name == "?o";
      const bool door = schema.name == "open" || schema.name == "close";
      EXPECT_EQ(interaction.local[a][p], item || door) << schema.name << " " << schema.parameters[p].name;
    }
  }
}

TEST_F(StackedDishes, StackingMakesDishesInteractButNotTheRest) {
  DomainInteraction interaction = analyze_interaction(*world_.domain);
  const ActionSchemaId unstack = *world_.domain->find_action("unstack");
  EXPECT_FALSE(interaction.local[unstack][0]);
  EXPECT_THAT(interaction.reason[unstack][0], HasSubstr("unstack changes (covered ?bottom)"));
  const ActionSchemaId pick_up = *world_.domain->find_action("pick-up");
  EXPECT_TRUE(interaction.local[pick_up][0]);

  // For the ketchup, every stackable dish is kept, and nothing else that is
  // not a place.
  const Goal goal = goal_or_die(world_, "(and (in ketchup1 fridge1) (closed fridge1))");
  Relevance relevance = analyze_relevance(*world_.domain, *world_.universe, world_.state, goal);
  auto kept = names(*world_.universe, relevance.objects);
  for (const char* dish : {"ceramic-plate1", "ceramic-plate2", "ceramic-bowl1", "ceramic-bowl2", "pot1", "pot-lid1"})
    EXPECT_THAT(kept, Contains(dish));
  for (const char* other : {"metal-fork1", "metal-fork2", "mustard1", "metal-spoon1", "milk1"})
    EXPECT_THAT(kept, Not(Contains(other)));
  EXPECT_EQ(relevance.kept_for_interaction, 6u);
  EXPECT_EQ(relevance.pruned, 5u);
  EXPECT_THAT(all_notes(relevance.notes), HasSubstr("6 items not in the goal are kept because they can interact"));
  EXPECT_THAT(all_notes(relevance.notes), HasSubstr("because unstack changes (covered ?bottom)"));
}

TEST_F(StackedDishes, TheBowlComesOffBeforeThePlateMoves) {
  const Goal goal = goal_or_die(world_, "(and (in ceramic-plate1 cupboard1) (closed cupboard1))");
  for (bool greedy : {true, false}) {
    SearchOptions options;
    options.max_depth = 8;
    PlanResult result = greedy ? find_greedy_plan(*world_.domain, *world_.universe, world_.state, goal, options)
                               : find_plan(*world_.domain, *world_.universe, world_.state, goal, options);
    ASSERT_EQ(result.status, SearchStatus::kSolved) << (greedy ? "greedy" : "iterative deepening");
    EXPECT_TRUE(plan_reaches(world_, result.plan, goal));
    auto steps = plan_text(world_, result.plan);
    auto unstack = std::find(steps.begin(), steps.end(), "(unstack ceramic-bowl1 ceramic-plate1 table1)");
    auto pick_up = std::find(steps.begin(), steps.end(), "(pick-up ceramic-plate1 table1)");
    ASSERT_NE(unstack, steps.end());
    ASSERT_NE(pick_up, steps.end());
    EXPECT_LT(unstack, pick_up);
    EXPECT_EQ(steps.size(), 6u);  // open, unstack, put the bowl down, pick up, put in, close
  }
}

TEST_F(StackedDishes, TheOldItemRuleWouldHavePrunedTheBowlAndFoundNoPlan) {
  // The rule before the analysis kept the goal's objects and every place.
  // Here that leaves the bowl out, and the plate can then never be lifted.
  const Goal goal = goal_or_die(world_, "(in ceramic-plate1 cupboard1)");
  std::vector<ObjectId> old_rule = goal.objects();
  for (ObjectId o = 0; o < world_.universe->size(); ++o)
    if (world_.universe->info(o).kind != ObjectKind::kItem) old_rule.push_back(o);
  std::sort(old_rule.begin(), old_rule.end());
  const State projected = project_state(world_.state, old_rule);
  const Fact covered = goal_or_die(world_, "(covered ceramic-plate1)").literals[0].fact;
  ASSERT_TRUE(projected.holds(covered));
  GroundTask task(*world_.domain, *world_.universe, old_rule, projected, goal);
  for (OperatorId o = 0; o < task.operator_count(); ++o)
    for (PropositionId p : task.list(task.op(o).deletes))
      EXPECT_NE(task.fact(p), covered) << "only unstacking the bowl uncovers the plate";
  FfHeuristic h(task);
  EXPECT_EQ(h.evaluate(task.initial().data(), nullptr), FfHeuristic::kDeadEnd);
  // The analysis keeps the bowl, and search finds the plan.
  PlanResult result = find_greedy_plan(*world_.domain, *world_.universe, world_.state, goal, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, result.plan, goal));
}

TEST_F(StackedDishes, TheWholeTaskIncludingTheDrawerInsideTheCupboard) {
  const Goal goal(scenario_.goal_assertions());
  PlanResult result = find_greedy_plan(*world_.domain, *world_.universe, world_.state, goal, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, result.plan, goal));
  auto steps = plan_text(world_, result.plan);
  // The drawer opens only inside the open cupboard, which closes over it.
  EXPECT_THAT(steps, Contains("(open-inner drawer1 cupboard2)"));
  EXPECT_THAT(steps, Contains("(close-outer cupboard2 drawer1)"));
  EXPECT_THAT(steps, Not(Contains("(open drawer1)")));
  // Without pruning the same task gives a plan of the same validity.
  SearchOptions off;
  off.prune_irrelevant = false;
  PlanResult full = find_greedy_plan(*world_.domain, *world_.universe, world_.state, goal, off);
  ASSERT_EQ(full.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world_, full.plan, goal));
}

TEST(Interaction, PruningTurnsItselfOffWhenEveryItemCanInteract) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/dish-tower.yaml"));
  const World& world = scenario.world;
  const Goal goal = goal_or_die(world, "(in ceramic-plate1 dishwasher1)");
  Relevance relevance = analyze_relevance(*world.domain, *world.universe, world.state, goal);
  EXPECT_EQ(relevance.objects.size(), world.universe->size());
  EXPECT_EQ(relevance.pruned, 0u);
  EXPECT_THAT(all_notes(relevance.notes), HasSubstr("0 pruned"));
  const Goal task(scenario.goal_assertions());
  PlanResult result = find_greedy_plan(*world.domain, *world.universe, world.state, task, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  EXPECT_TRUE(plan_reaches(world, result.plan, task));
}

TEST(Interaction, PruningIsOffWhenTheHandStartsInconsistentOrTheGoalWantsItFull) {
  Scenario scenario = testing::tidy_kitchen();
  const World& world = scenario.world;
  const Vocabulary& v = world.vocabulary;
  // The goal wants the hand full: a plan may have to pick up anything.
  const Goal full_hand = goal_or_die(world, "(not (handempty))");
  Relevance r1 = analyze_relevance(*world.domain, *world.universe, world.state, full_hand);
  EXPECT_EQ(r1.objects.size(), world.universe->size());
  EXPECT_THAT(all_notes(r1.notes), HasSubstr("relevance pruning is off: the goal asks for (handempty) to be false"));
  // A state that holds an item and an empty hand at once.
  std::vector<Fact> facts(world.state.facts().begin(), world.state.facts().end());
  facts.push_back(Fact(v.holding, {*world.universe->find("mug1")}));
  Relevance r2 = analyze_relevance(*world.domain, *world.universe, State(facts), goal_or_die(world, "(closed fridge1)"));
  EXPECT_EQ(r2.objects.size(), world.universe->size());
  EXPECT_THAT(all_notes(r2.notes), HasSubstr("does not hold exactly one of (handempty) and (holding ?x)"));
}

TEST(Interaction, ADomainWithoutAOneArmHandKeepsItemsThatTouchZeroArgumentFacts) {
  // Here (free) can come back while an item is still carried (shrug), so
  // at most one item in hand is not guaranteed: no one-arm hand is found,
  // and an action that takes (free) is not local to its item.
  auto domain = parse_domain(R"(
    (define (domain two-arms)
      (:requirements :strips :typing)
      (:types item place - object)
      (:predicates (at ?o - item ?p - place) (carried ?o - item) (free))
      (:action take :parameters (?o - item ?p - place)
        :precondition (and (at ?o ?p) (free))
        :effect (and (carried ?o) (not (at ?o ?p)) (not (free))))
      (:action drop :parameters (?o - item ?p - place)
        :precondition (carried ?o)
        :effect (and (at ?o ?p) (free) (not (carried ?o))))
      (:action shrug :parameters (?o - item)
        :precondition (carried ?o)
        :effect (free)))
  )", "two-arms.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  DomainInteraction interaction = analyze_interaction(*domain);
  EXPECT_TRUE(interaction.hands.empty());  // shrug adds (free) without freeing a held item
  EXPECT_FALSE(interaction.local[0][0]);
  EXPECT_THAT(interaction.reason[0][0], HasSubstr("take changes (free)"));
}

TEST(Interaction, ScenarioFactsAreCheckedLikeGoals) {
  const std::string base = R"(
name: t
domain: )" + testing::source_path("data/domains/kitchen-stacking.pddl").string() + R"(
places: [{category: table, kind: surface}, {category: cupboard, kind: receptacle, door: closed}]
objects: [{category: plate, at: table1, count: 2}]
task: {name: tidy, subtasks: [{verb: clear, place: table1}]}
intent: [{subtask: clear, category: plate, receptacle: cupboard1}]
)";
  auto ok = parse_scenario(base + "facts: ['(stackable plate1)', '(stacked plate2 plate1)']\n", "t.yaml");
  ASSERT_TRUE(ok.has_value()) << ok.error().describe();
  EXPECT_TRUE(ok->world.state.holds(goal_or_die(ok->world, "(stacked plate2 plate1)").literals[0].fact));
  for (const auto& [facts, message] : std::vector<std::pair<std::string, std::string>>{
           {"facts: ['(stacked plate3 plate1)']", "there is no plate3"},
           {"facts: ['(on plate1 table1)']", "(on ...) comes from places and objects, not from facts"},
           {"facts: ['(not (covered plate1))']", "expected facts that hold"},
           {"facts: '(covered plate1)'", "expected 'facts': a list"}}) {
    auto bad = parse_scenario(base + facts + "\n", "t.yaml");
    ASSERT_FALSE(bad.has_value()) << facts;
    EXPECT_THAT(bad.error().message, HasSubstr(message)) << facts;
    EXPECT_THAT(bad.error().message, HasSubstr("t.yaml:")) << facts;
  }
}

}  // namespace
}  // namespace apprentice
