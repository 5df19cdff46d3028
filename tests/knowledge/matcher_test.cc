// The rule matcher: rules learned on one object propose, and select, the
// actions for another object with the same goal, without search or
// instruction; kFull rules generalize further than the paper's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/matcher.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;
using namespace apprentice::testing;

class Matcher : public ::testing::Test {
 protected:
  Scenario scenario_ = tidy_kitchen();
  const World& world_ = scenario_.world;
  const Domain& domain_ = *world_.domain;

  RuleMatcher plate_rules(Generalization g) const { return matcher_of(world_, learn(world_, ceramic_plate_episode(world_), g)); }

  // The state once the ceramic plate has been cleared, as the agent would
  // find the kitchen when it turns to the next object.
  State after_plate() const {
    return after(world_, world_.state,
                 {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                  "(close dishwasher1)"});
  }

  std::vector<std::string> proposals(const RuleMatcher& m, const State& state, const Goal& goal, std::string_view object_id,
                                     std::string_view subtask) const {
    MatchQuery query{&state, &goal, object(world_, object_id), subtask};
    std::vector<std::string> out;
    for (const Proposal& p : m.propose(domain_, *world_.universe, query))
      out.push_back(format_action(domain_, *world_.universe, p.action) + " " + std::to_string(p.steps_to_goal));
    return out;
  }

  // Follows the selected proposal from `state` until the goal holds, at
  // most 10 steps: the actions taken, or with "STUCK" appended where no
  // rule proposed anything.
  std::vector<std::string> follow(const RuleMatcher& m, State state, const Goal& goal, std::string_view object_id,
                                  std::string_view subtask) const {
    std::vector<std::string> taken;
    for (int i = 0; i < 10 && !goal.satisfied_by(state); ++i) {
      MatchQuery query{&state, &goal, object(world_, object_id), subtask};
      auto selected = m.select(domain_, *world_.universe, query);
      if (!selected) {
        taken.push_back("STUCK");
        return taken;
      }
      taken.push_back(format_action(domain_, *world_.universe, selected->action));
      EXPECT_TRUE(is_applicable(domain_, state, selected->action)) << taken.back();
      if (!is_applicable(domain_, state, selected->action)) return taken;
      state = apply(domain_, state, selected->action);
    }
    return taken;
  }
};

TEST_F(Matcher, MetalForkAfterCeramicPlateProposesOpenDishwasherFirst) {
  for (Generalization g : {Generalization::kFull, Generalization::kPaper}) {
    RuleMatcher m = plate_rules(g);
    Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
    EXPECT_THAT(proposals(m, after_plate(), fork, "metal-fork1", "clear"), ElementsAre("(open dishwasher1) 4"))
        << to_string(g);
  }
}

TEST_F(Matcher, MetalForkAfterCeramicPlateReachesTheGoalWithRulesAlone) {
  for (Generalization g : {Generalization::kFull, Generalization::kPaper}) {
    RuleMatcher m = plate_rules(g);
    Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
    // From the initial state (the plate still on the table) and from the
    // kitchen as the plate left it.
    for (const State& from : {world_.state, after_plate()})
      EXPECT_THAT(follow(m, from, fork, "metal-fork1", "clear"),
                  ElementsAre("(open dishwasher1)", "(pick-up metal-fork1 table1)", "(put-in metal-fork1 dishwasher1)",
                              "(close dishwasher1)"))
          << to_string(g);
  }
}

TEST_F(Matcher, ProposalsTrackTheStateStepByStep) {
  RuleMatcher m = plate_rules(Generalization::kPaper);
  Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
  State open = after(world_, after_plate(), {"(open dishwasher1)"});
  EXPECT_THAT(proposals(m, open, fork, "metal-fork1", "clear"), ElementsAre("(pick-up metal-fork1 table1) 3"));
  State holding = after(world_, open, {"(pick-up metal-fork1 table1)"});
  EXPECT_THAT(proposals(m, holding, fork, "metal-fork1", "clear"), ElementsAre("(put-in metal-fork1 dishwasher1) 2"));
  State in = after(world_, holding, {"(put-in metal-fork1 dishwasher1)"});
  EXPECT_THAT(proposals(m, in, fork, "metal-fork1", "clear"), ElementsAre("(close dishwasher1) 1"));
}

TEST_F(Matcher, FullRulesOpenAnyClosedReceptacleTheGoalNeeds) {
  // Learned only from the dishwasher, the kFull open rule opens the fridge
  // for the ketchup: the paper's "future work".
  RuleMatcher m = plate_rules(Generalization::kFull);
  Goal ketchup = goal(world_, "(and (in ketchup1 fridge1) (closed fridge1))");
  EXPECT_THAT(proposals(m, after_plate(), ketchup, "ketchup1", "clear"), ElementsAre("(open fridge1) 4"));
  EXPECT_THAT(follow(m, after_plate(), ketchup, "ketchup1", "clear"),
              ElementsAre("(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)", "(close fridge1)"));
}

TEST_F(Matcher, PaperRulesOpenOnlyTheDishwasher) {
  RuleMatcher m = plate_rules(Generalization::kPaper);
  Goal ketchup = goal(world_, "(and (in ketchup1 fridge1) (closed fridge1))");
  EXPECT_THAT(proposals(m, after_plate(), ketchup, "ketchup1", "clear"), IsEmpty());
  // The paper's pick-up rule tests only the table, not the receptacle: once
  // the fridge is open, it serves the ketchup too.
  State open = after(world_, after_plate(), {"(open fridge1)"});
  EXPECT_THAT(proposals(m, open, ketchup, "ketchup1", "clear"), ElementsAre("(pick-up ketchup1 table1) 3"));
}

TEST_F(Matcher, PaperRulesForClearDoNotFireForStore) {
  RuleMatcher m = plate_rules(Generalization::kPaper);
  Goal mug = goal(world_, "(and (in mug1 dishwasher1) (closed dishwasher1))");
  EXPECT_THAT(proposals(m, after_plate(), mug, "mug1", "store"), IsEmpty());
  // Not even where only the subtask differs: a plate on the table, stored.
  Goal plate2 = goal(world_, "(and (in ceramic-plate2 dishwasher1) (closed dishwasher1))");
  EXPECT_THAT(proposals(m, after_plate(), plate2, "ceramic-plate2", "store"), IsEmpty());
  EXPECT_THAT(proposals(m, after_plate(), plate2, "ceramic-plate2", "clear"), ElementsAre("(open dishwasher1) 4"));
}

TEST_F(Matcher, FullRulesServeAnySubtask) {
  // One rule across subtasks: the mug on the counter is stored with the
  // rules learned clearing the plate from the table.
  RuleMatcher m = plate_rules(Generalization::kFull);
  Goal mug = goal(world_, "(and (in mug1 dishwasher1) (closed dishwasher1))");
  EXPECT_THAT(follow(m, after_plate(), mug, "mug1", "store"),
              ElementsAre("(open dishwasher1)", "(pick-up mug1 counter1)", "(put-in mug1 dishwasher1)",
                          "(close dishwasher1)"));
}

TEST_F(Matcher, NoProposalWhenTheGoalShapeDiffers) {
  for (Generalization g : {Generalization::kFull, Generalization::kPaper}) {
    RuleMatcher m = plate_rules(g);
    // One literal fewer (no door to close), one more, or a negated one.
    EXPECT_THAT(proposals(m, after_plate(), goal(world_, "(in metal-fork1 dishwasher1)"), "metal-fork1", "clear"),
                IsEmpty());
    EXPECT_THAT(proposals(m, after_plate(),
                          goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1) (closed fridge1))"),
                          "metal-fork1", "clear"),
                IsEmpty());
    EXPECT_THAT(proposals(m, after_plate(),
                          goal(world_, "(and (in metal-fork1 dishwasher1) (not (closed dishwasher1)))"),
                          "metal-fork1", "clear"),
                IsEmpty());
  }
}

TEST_F(Matcher, TheObjectOfInterestIsTheOneTheRuleActsOn) {
  // The goal is about the fork; the plate on the table is not picked up in
  // its place, and no rule fires for a goal about another object.
  RuleMatcher m = plate_rules(Generalization::kFull);
  Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
  State open = after(world_, world_.state, {"(open dishwasher1)"});
  EXPECT_THAT(proposals(m, open, fork, "metal-fork1", "clear"), ElementsAre("(pick-up metal-fork1 table1) 3"));
  EXPECT_THAT(proposals(m, open, fork, "ceramic-plate1", "clear"), IsEmpty());
}

TEST_F(Matcher, RulesLearnedInOneKitchenServeAnother) {
  RuleMatcher m = plate_rules(Generalization::kPaper);
  Scenario similar = tidy_kitchen_similar();
  const World& w = similar.world;
  Goal plate = goal(w, "(and (in ceramic-plate3 dishwasher1) (closed dishwasher1))");
  State state = w.state;
  std::vector<std::string> taken;
  for (int i = 0; i < 10 && !plate.satisfied_by(state); ++i) {
    MatchQuery query{&state, &plate, object(w, "ceramic-plate3"), "clear"};
    auto selected = m.select(*w.domain, *w.universe, query);
    ASSERT_TRUE(selected.has_value()) << "stuck after " << taken.size() << " actions";
    taken.push_back(format_action(*w.domain, *w.universe, selected->action));
    state = apply(*w.domain, state, selected->action);
  }
  EXPECT_THAT(taken, ElementsAre("(open dishwasher1)", "(pick-up ceramic-plate3 table1)",
                                 "(put-in ceramic-plate3 dishwasher1)", "(close dishwasher1)"));
}

TEST_F(Matcher, SelectPrefersFewestStepsThenTheEarliestRule) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  const Rule& open = rules[3];
  // A pick-up rule that fires wherever the open rule fires (it has the
  // open rule's conditions) but claims more steps to the goal.
  Rule slow_pick_up = rules[2];
  slow_pick_up.conditions = open.conditions;
  slow_pick_up.steps_to_goal = 9;
  RuleMatcher m;
  m.add(domain_, open);
  m.add(domain_, slow_pick_up);
  Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
  EXPECT_THAT(proposals(m, after_plate(), fork, "metal-fork1", "clear"),
              ElementsAre("(open dishwasher1) 4", "(pick-up metal-fork1 table1) 9"));
  MatchQuery query{&world_.state, &fork, object(world_, "metal-fork1"), "clear"};
  ASSERT_TRUE(m.select(domain_, *world_.universe, query).has_value());
  EXPECT_EQ(m.select(domain_, *world_.universe, query)->action, action(world_, "(open dishwasher1)"));

  // Fewer steps win whatever the order of the rules.
  Rule quick_pick_up = slow_pick_up;
  quick_pick_up.steps_to_goal = 2;
  RuleMatcher m2;
  m2.add(domain_, open);
  m2.add(domain_, quick_pick_up);
  ASSERT_TRUE(m2.select(domain_, *world_.universe, query).has_value());
  EXPECT_EQ(m2.select(domain_, *world_.universe, query)->action, action(world_, "(pick-up metal-fork1 table1)"));
  EXPECT_EQ(m2.select(domain_, *world_.universe, query)->rule_index, 1u);

  // At equal steps, the rule learned first.
  Rule tied_pick_up = slow_pick_up;
  tied_pick_up.steps_to_goal = 4;
  RuleMatcher m3;
  m3.add(domain_, tied_pick_up);
  m3.add(domain_, open);
  ASSERT_TRUE(m3.select(domain_, *world_.universe, query).has_value());
  EXPECT_EQ(m3.select(domain_, *world_.universe, query)->rule_index, 0u);
}

TEST_F(Matcher, AnActionProposedByTwoRulesIsListedOnceWithTheFewerSteps) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  Rule slower_open = rules[3];
  slower_open.steps_to_goal = 7;
  RuleMatcher m;
  m.add(domain_, slower_open);
  m.add(domain_, rules[3]);
  Goal fork = goal(world_, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
  EXPECT_THAT(proposals(m, after_plate(), fork, "metal-fork1", "clear"), ElementsAre("(open dishwasher1) 4"));
}

TEST_F(Matcher, AddingTheSameRuleTwiceKeepsOne) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  RuleMatcher m;
  for (const Rule& r : rules) EXPECT_TRUE(m.add(domain_, r));
  for (const Rule& r : rules) EXPECT_FALSE(m.add(domain_, r));
  EXPECT_EQ(m.size(), rules.size());
  // The fork's episode teaches the same rules: nothing new.
  Episode fork = make_episode(world_, after_plate(), "metal-fork1",
                              "(and (in metal-fork1 dishwasher1) (closed dishwasher1))", "clear",
                              {"(open dishwasher1)", "(pick-up metal-fork1 table1)",
                               "(put-in metal-fork1 dishwasher1)", "(close dishwasher1)"});
  for (const Rule& r : learn(world_, fork, Generalization::kFull)) EXPECT_FALSE(m.add(domain_, r));
}

TEST_F(Matcher, EveryProposalIsApplicable) {
  // From every state of every object's way to the dishwasher, whatever the
  // rules propose can be done.
  for (Generalization g : {Generalization::kFull, Generalization::kPaper}) {
    RuleMatcher m = plate_rules(g);
    for (const char* item : {"metal-fork1", "glass-tumbler1", "ceramic-plate2"}) {
      Goal target = goal(world_, "(and (in " + std::string(item) + " dishwasher1) (closed dishwasher1))");
      State state = after_plate();
      for (int i = 0; i < 6 && !target.satisfied_by(state); ++i) {
        MatchQuery query{&state, &target, object(world_, item), "clear"};
        auto all = m.propose(domain_, *world_.universe, query);
        ASSERT_FALSE(all.empty()) << item;
        for (const Proposal& p : all)
          EXPECT_TRUE(is_applicable(domain_, state, p.action)) << format_action(domain_, *world_.universe, p.action);
        state = apply(domain_, state, all.front().action);
      }
      EXPECT_TRUE(target.satisfied_by(state)) << item << " " << to_string(g);
    }
  }
}

}  // namespace
}  // namespace apprentice
