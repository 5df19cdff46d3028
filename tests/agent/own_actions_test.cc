// The agent's own next action (agent/own_actions.h), on the paper's
// kitchen: a plan search found is carried out step by step without
// searching again, search that failed is not run again in the same state,
// and a learned rule comes before search.
#include "agent/own_actions.h"

#include <gtest/gtest.h>

#include "agent_fixtures.h"
#include "world/action.h"
#include "world/goal.h"

namespace apprentice {
namespace {

class OwnActionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    kitchen_ = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
    auto goal = parse_goal(*world().domain, *world().universe, "(and (in ketchup1 fridge1) (closed fridge1))");
    ASSERT_TRUE(goal) << goal.error().message;
    goal_ = *goal;
    ketchup_ = *world().universe->find("ketchup1");
  }
  World& world() { return kitchen_.world; }
  Scenario kitchen_;
  Goal goal_;
  ObjectId ketchup_ = 0;
};

TEST_F(OwnActionsTest, APlanFoundIsCarriedOutWithoutSearchingAgain) {
  OwnActions own;
  OwnActions::Ways ways;
  ways.search_depth = 4;
  OwnActions::Next first = own.next(world(), goal_, ketchup_, "clear", ways);
  ASSERT_TRUE(first.action.has_value());
  EXPECT_EQ(first.source, "search");
  EXPECT_TRUE(first.searched);
  EXPECT_GT(first.nodes, 0u);
  int steps = 1;
  world().state = apply(*world().domain, world().state, *first.action);
  while (!goal_.satisfied_by(world().state)) {
    OwnActions::Next next = own.next(world(), goal_, ketchup_, "clear", ways);
    ASSERT_TRUE(next.action.has_value()) << "after " << steps << " steps";
    EXPECT_FALSE(next.searched) << "the plan is carried on, not searched again";
    world().state = apply(*world().domain, world().state, *next.action);
    ASSERT_LT(++steps, 10);
  }
  EXPECT_GE(steps, 3) << "open the fridge, pick up, put in, close";
}

TEST_F(OwnActionsTest, SearchThatFailedIsNotRunAgainInTheSameState) {
  OwnActions own;
  OwnActions::Ways ways;
  ways.search_depth = 1;  // too shallow for the fridge
  OwnActions::Next first = own.next(world(), goal_, ketchup_, "clear", ways);
  EXPECT_FALSE(first.action.has_value());
  EXPECT_TRUE(first.searched);
  OwnActions::Next again = own.next(world(), goal_, ketchup_, "clear", ways);
  EXPECT_FALSE(again.action.has_value());
  EXPECT_FALSE(again.searched);
  // Without any way of its own, the agent has no action and does not search.
  OwnActions none;
  OwnActions::Next nothing = none.next(world(), goal_, ketchup_, "clear", OwnActions::Ways{});
  EXPECT_FALSE(nothing.action.has_value());
  EXPECT_FALSE(nothing.searched);
}

TEST_F(OwnActionsTest, ALearnedRuleComesBeforeSearch) {
  // The rules learned for the kitchen by the paper's inst+search4.
  testing::LearningRun run = testing::learn(kitchen_, "inst+search4");
  ASSERT_TRUE(run.report.has_value());
  ASSERT_GT(run.knowledge.rules.size(), 0u);
  OwnActions own;
  OwnActions::Ways ways;
  ways.rules = &run.knowledge.rules;
  ways.search_depth = 4;
  OwnActions::Next first = own.next(world(), goal_, ketchup_, "clear", ways);
  ASSERT_TRUE(first.action.has_value());
  EXPECT_EQ(first.source, "rule");
  EXPECT_FALSE(first.searched);
}

}  // namespace
}  // namespace apprentice
