// Why a goal can never hold (search/unreachable.h): the literal found is
// one the planners cannot reach, and the reason is read off the action
// model: no action makes it hold; a static precondition the object lacks;
// an object of the wrong type for the only action; a precondition that can
// never hold either, explained in turn.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "search/greedy_best_first.h"
#include "search/unreachable.h"
#include "common/world_helpers.h"
#include "search_fixtures.h"

namespace apprentice {
namespace {

using ::testing::SizeIs;
using testing::goal_or_die;
using Kind = UnreachableBlocker::Kind;
using Reason = UnreachableLiteral::Reason;

class Unreachable : public ::testing::Test {
 protected:
  Scenario kitchen_ = testing::tidy_kitchen();
  const World& world_ = kitchen_.world;

  UnreachableChain explain(const World& world, std::string_view goal_text) const {
    return explain_unreachable(*world.domain, *world.universe, world.state, goal_or_die(world, goal_text));
  }
  Literal literal(const World& world, std::string_view text) const { return goal_or_die(world, text).literals.at(0); }
  // The planner agrees: no plan exists.
  void expect_no_plan(const World& world, std::string_view goal_text) const {
    PlanResult r = find_greedy_plan(*world.domain, *world.universe, world.state, goal_or_die(world, goal_text), {});
    EXPECT_EQ(r.status, SearchStatus::kExhausted) << goal_text;
  }
};

// A world of a small domain, from PDDL text.
struct PddlWorld {
  std::shared_ptr<const Domain> domain;
  World world;
};
PddlWorld pddl_world(std::string_view domain_text, std::string_view problem_text) {
  auto domain = parse_domain(domain_text, "test-domain.pddl");
  if (!domain) ADD_FAILURE() << domain.error().describe();
  PddlWorld out;
  out.domain = std::make_shared<const Domain>(std::move(*domain));
  auto problem = parse_problem(*out.domain, problem_text, "test-problem.pddl");
  if (!problem) ADD_FAILURE() << problem.error().describe();
  out.world.domain = out.domain;
  out.world.universe = std::make_shared<const Universe>(std::move(problem->universe));
  out.world.state = problem->init;
  return out;
}

TEST_F(Unreachable, ALidlessBinLacksTheStaticPreconditionOfClose) {
  expect_no_plan(world_, "(closed garbage1)");
  UnreachableChain chain = explain(world_, "(closed garbage1)");
  ASSERT_THAT(chain, SizeIs(1));
  EXPECT_EQ(chain[0].literal, literal(world_, "(closed garbage1)"));
  EXPECT_EQ(chain[0].reason, Reason::kNoActionApplies);
  ASSERT_THAT(chain[0].blockers, SizeIs(1));  // close is the only action that adds (closed ?r)
  const UnreachableBlocker& b = chain[0].blockers[0];
  EXPECT_EQ(b.kind, Kind::kStaticPrecondition);
  EXPECT_EQ(b.schema, *world_.domain->find_action("close"));
  EXPECT_EQ(b.precondition, literal(world_, "(openable garbage1)"));
  ASSERT_TRUE(b.action.has_value());
  EXPECT_EQ(*b.action, testing::action(world_, "(close garbage1)"));
}

TEST_F(Unreachable, NoActionDeletesAnAffordance) {
  expect_no_plan(world_, "(not (grabbable ketchup1))");
  UnreachableChain chain = explain(world_, "(and (in ketchup1 fridge1) (not (grabbable ketchup1)))");
  ASSERT_THAT(chain, SizeIs(1));
  EXPECT_EQ(chain[0].literal, literal(world_, "(not (grabbable ketchup1))"));
  EXPECT_EQ(chain[0].reason, Reason::kNoAction);
  EXPECT_THAT(chain[0].blockers, SizeIs(0));
}

TEST_F(Unreachable, GoalsThatCanHoldOrOnlyConflictHaveNoChain) {
  EXPECT_THAT(explain(world_, "(and (in ketchup1 fridge1) (closed fridge1))"), SizeIs(0));
  EXPECT_THAT(explain(world_, "(closed fridge1)"), SizeIs(0));  // already so
  // Each part can hold, but not both: the hand holds the ketchup or is empty.
  expect_no_plan(world_, "(and (holding ketchup1) (handempty))");
  EXPECT_THAT(explain(world_, "(and (holding ketchup1) (handempty))"), SizeIs(0));
}

TEST_F(Unreachable, AnItemThatCannotBePickedUpExplainsWhyItCannotBePutAway) {
  PddlWorld w = pddl_world(read_text_file(testing::source_path("data/domains/kitchen.pddl")).value(), R"(
    (define (problem rock) (:domain kitchen)
      (:objects rock1 - item table1 - surface-place fridge1 - receptacle-place)
      (:init (on rock1 table1) (surface table1) (receptacle fridge1) (openable fridge1) (handempty))
      (:goal (in rock1 fridge1))))");
  expect_no_plan(w.world, "(in rock1 fridge1)");
  UnreachableChain chain = explain(w.world, "(in rock1 fridge1)");
  ASSERT_THAT(chain, SizeIs(2));
  ASSERT_THAT(chain[0].blockers, SizeIs(1));  // put-in
  EXPECT_EQ(chain[0].blockers[0].kind, Kind::kPreconditionNeverHolds);
  EXPECT_EQ(chain[0].blockers[0].precondition, literal(w.world, "(holding rock1)"));
  EXPECT_EQ(chain[1].literal, literal(w.world, "(holding rock1)"));
  ASSERT_THAT(chain[1].blockers, SizeIs(2));  // pick-up, pick-up-from
  for (const UnreachableBlocker& b : chain[1].blockers) {
    EXPECT_EQ(b.kind, Kind::kStaticPrecondition);
    EXPECT_EQ(b.precondition, literal(w.world, "(grabbable rock1)"));
    EXPECT_FALSE(b.action.has_value());  // the goal does not name the place it is taken from
  }
}

TEST_F(Unreachable, AnObjectOfTheWrongTypeForTheOnlyActionIsNamed) {
  // (in ?o ?p) is declared for any item, but only sturdy items are shelved.
  PddlWorld w = pddl_world(R"(
    (define (domain shelving)
      (:requirements :strips :typing)
      (:types item place - object sturdy fragile - item)
      (:predicates (in ?o - item ?p - place) (loose ?o - item))
      (:action shelve :parameters (?o - sturdy ?p - place)
        :precondition (loose ?o)
        :effect (and (in ?o ?p) (not (loose ?o)))))
  )", R"(
    (define (problem vases) (:domain shelving)
      (:objects vase1 - fragile box1 - sturdy shelf1 - place)
      (:init (loose vase1) (loose box1))
      (:goal (in vase1 shelf1))))");
  EXPECT_THAT(explain(w.world, "(in box1 shelf1)"), SizeIs(0));
  expect_no_plan(w.world, "(in vase1 shelf1)");
  UnreachableChain chain = explain(w.world, "(in vase1 shelf1)");
  ASSERT_THAT(chain, SizeIs(1));
  ASSERT_THAT(chain[0].blockers, SizeIs(1));
  const UnreachableBlocker& b = chain[0].blockers[0];
  EXPECT_EQ(b.kind, Kind::kWrongType);
  EXPECT_EQ(b.object, testing::object(w.world, "vase1"));
  EXPECT_EQ(b.type, *w.domain->find_type("sturdy"));
}

TEST_F(Unreachable, NoActionAddsThePredicate) {
  PddlWorld w = pddl_world(R"(
    (define (domain breaking)
      (:requirements :strips :typing)
      (:types item)
      (:predicates (broken ?o - item) (whole ?o - item))
      (:action mend :parameters (?o - item)
        :precondition (broken ?o)
        :effect (and (whole ?o) (not (broken ?o)))))
  )", R"(
    (define (problem vase) (:domain breaking)
      (:objects vase1 - item)
      (:init (whole vase1))
      (:goal (broken vase1))))");
  expect_no_plan(w.world, "(broken vase1)");
  UnreachableChain chain = explain(w.world, "(broken vase1)");
  ASSERT_THAT(chain, SizeIs(1));
  EXPECT_EQ(chain[0].reason, Reason::kNoAction);
  // (whole vase1) holds, and no action deletes (whole ?o).
  UnreachableChain unwhole = explain(w.world, "(not (whole vase1))");
  ASSERT_THAT(unwhole, SizeIs(1));
  EXPECT_EQ(unwhole[0].reason, Reason::kNoAction);
}

}  // namespace
}  // namespace apprentice
