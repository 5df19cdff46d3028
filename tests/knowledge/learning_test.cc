// Policy learning by regressing the goal through the executed actions:
// one rule per contributing action, conditions only what the rest of the
// plan depended on, objects turned into variables.
#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/learning.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using namespace apprentice::testing;

class Learning : public ::testing::Test {
 protected:
  Scenario scenario_ = tidy_kitchen();
  const World& world_ = scenario_.world;
  const Domain& domain_ = *world_.domain;

  std::string action_name(const Rule& rule) const { return domain_.actions.at(rule.action).name; }
  std::string signature(const Rule& rule) const { return rule_signature(domain_, rule); }
};

TEST_F(Learning, CeramicPlateGivesOneRulePerActionLastActionFirst) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  ASSERT_EQ(rules.size(), 4u);
  std::vector<std::string> actions;
  std::vector<int> steps;
  for (const Rule& r : rules) {
    actions.push_back(action_name(r));
    steps.push_back(r.steps_to_goal);
  }
  EXPECT_THAT(actions, ElementsAre("close", "put-in", "pick-up", "open"));
  EXPECT_THAT(steps, ElementsAre(1, 2, 3, 4));
}

TEST_F(Learning, OpenRuleTestsExactlyWhatTheRestOfThePlanNeeded) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  ASSERT_EQ(rules.size(), 4u);
  // The dishwasher is closed, the hand is empty (to open it, and later to
  // pick the plate up), and the plate is on some surface (to pick it up):
  // the paper's "dishwasher closed, holding_object = false, not grabbed".
  EXPECT_EQ(signature(rules[3]),
            "open(?r) <- interest(?o) goal{(in ?o ?r) (closed ?r)} state{(on ?o ?s) (handempty) (closed ?r) "
            "(grabbable ?o) (openable ?r) (receptacle ?r) (surface ?s)} steps=4");
  // The close rule needs the plate already in, the door open and the hand
  // empty; nothing about surfaces.
  EXPECT_EQ(signature(rules[0]),
            "close(?r) <- interest(?o) goal{(in ?o ?r) (closed ?r)} state{(in ?o ?r) (handempty) "
            "(not (closed ?r)) (openable ?r)} steps=1");
  // Put-in: holding the plate, the door open; (openable ?r) is kept because
  // the close after it needs it.
  EXPECT_EQ(signature(rules[1]),
            "put-in(?o, ?r) <- interest(?o) goal{(in ?o ?r) (closed ?r)} state{(holding ?o) (not (closed ?r)) "
            "(openable ?r) (receptacle ?r)} steps=2");
}

TEST_F(Learning, GoalOfEveryRuleIsTheWholeGeneralizedGoal) {
  for (Generalization g : {Generalization::kFull, Generalization::kPaper}) {
    for (const Rule& r : learn(world_, ceramic_plate_episode(world_), g))
      EXPECT_THAT(signature(r), HasSubstr("goal{(in ?o ?r) (closed ?r)}")) << to_string(g);
  }
}

TEST_F(Learning, StepsCountOnlyContributingActions) {
  // A detour in the middle (open and close the fridge) neither shifts the
  // step counts nor gives rules.
  Episode episode = make_episode(world_, world_.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(open dishwasher1)", "(open fridge1)", "(pick-up ceramic-plate1 table1)",
                                  "(put-in ceramic-plate1 dishwasher1)", "(close dishwasher1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kFull);
  ASSERT_EQ(rules.size(), 4u);
  EXPECT_THAT(signatures(world_, rules), ::testing::ContainerEq(signatures(
                                             world_, learn(world_, ceramic_plate_episode(world_), Generalization::kFull))));
}

TEST_F(Learning, DetoursGiveNoRule) {
  // Opening and closing the fridge, and opening the cupboard and leaving it
  // open, contribute nothing to the goal: no rule mentions them.
  Episode episode = make_episode(world_, world_.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(open fridge1)", "(close fridge1)", "(open cupboard1)", "(open dishwasher1)",
                                  "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                                  "(close dishwasher1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kPaper);
  ASSERT_EQ(rules.size(), 4u);
  for (const Rule& r : rules) {
    EXPECT_THAT(signature(r), Not(HasSubstr("fridge")));
    EXPECT_THAT(signature(r), Not(HasSubstr("cupboard")));
  }
  EXPECT_EQ(signatures(world_, rules),
            signatures(world_, learn(world_, ceramic_plate_episode(world_), Generalization::kPaper)));
}

TEST_F(Learning, ActionsThatUndoThemselvesGiveNoRule) {
  // Opening the dishwasher, closing it again and then doing the real work:
  // the first two actions lead back to the state they started from.
  Episode episode = make_episode(world_, world_.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(open dishwasher1)", "(close dishwasher1)", "(open dishwasher1)",
                                  "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                                  "(close dishwasher1)"});
  EXPECT_EQ(signatures(world_, learn(world_, episode, Generalization::kFull)),
            signatures(world_, learn(world_, ceramic_plate_episode(world_), Generalization::kFull)));
}

TEST_F(Learning, PickingUpAnotherItemAndPuttingItBackGivesNoRule) {
  Episode episode = make_episode(world_, world_.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(pick-up metal-fork1 table1)", "(put-on metal-fork1 table1)", "(open dishwasher1)",
                                  "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                                  "(close dishwasher1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kPaper);
  EXPECT_EQ(signatures(world_, rules),
            signatures(world_, learn(world_, ceramic_plate_episode(world_), Generalization::kPaper)));
  // The provenance of each rule is still the action it was learned from.
  ASSERT_EQ(rules.size(), 4u);
  EXPECT_EQ(rules[3].provenance.source, "instructor: \"(open dishwasher1)\"");
}

TEST_F(Learning, VariableNamesFollowTheKindOfObject) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  const Rule& pick_up = rules[2];
  ASSERT_EQ(action_name(pick_up), "pick-up");
  ASSERT_GE(pick_up.variables.size(), 3u);
  // The object of interest is always variable 0, ?o.
  EXPECT_EQ(pick_up.variables[0].name, "?o");
  EXPECT_TRUE(pick_up.variables[0].object_of_interest);
  std::vector<std::string> names;
  for (const RuleVariable& v : pick_up.variables) names.push_back(v.name);
  EXPECT_THAT(names, ElementsAre("?o", "?r", "?s"));
  for (std::size_t i = 1; i < pick_up.variables.size(); ++i) EXPECT_FALSE(pick_up.variables[i].object_of_interest);
}

TEST_F(Learning, SecondReceptacleIsR2) {
  // Unloading a bowl from the dish rack into the cupboard: the bowl starts
  // in one receptacle and ends in another.
  Episode episode = make_episode(world_, world_.state, "ceramic-bowl1",
                                 "(and (in ceramic-bowl1 cupboard1) (closed cupboard1))", "unload",
                                 {"(open cupboard1)", "(pick-up-from ceramic-bowl1 dish-rack1)",
                                  "(put-in ceramic-bowl1 cupboard1)", "(close cupboard1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kPaper);
  ASSERT_EQ(rules.size(), 4u);
  EXPECT_EQ(signature(rules[2]),
            "pick-up-from(?o, ?r2) <- subtask=unload interest(?o) category(?r2)=dish-rack goal{(in ?o ?r) (closed ?r)} "
            "state{(in ?o ?r2) (handempty) (not (closed ?r)) (not (closed ?r2)) (grabbable ?o) (openable ?r) "
            "(receptacle ?r) (receptacle ?r2)} steps=3");
}

TEST_F(Learning, AnotherItemIsX) {
  // The hand must be emptied of another item first: it becomes ?x.
  State holding_fork = after(world_, world_.state, {"(pick-up metal-fork1 table1)"});
  Episode episode = make_episode(world_, holding_fork, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(put-on metal-fork1 table1)", "(open dishwasher1)",
                                  "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                                  "(close dishwasher1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kFull);
  ASSERT_EQ(rules.size(), 5u);
  EXPECT_EQ(signature(rules[4]),
            "put-on(?x, ?s) <- interest(?o) goal{(in ?o ?r) (closed ?r)} state{(on ?o ?s) (holding ?x) (closed ?r) "
            "(grabbable ?o) (openable ?r) (receptacle ?r) (surface ?s)} steps=5");
}

TEST_F(Learning, PaperAddsSubtaskAndCategoriesOfManipulatedObjectsOnly) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kPaper);
  ASSERT_EQ(rules.size(), 4u);
  for (const Rule& r : rules) {
    EXPECT_EQ(r.subtask, std::optional<std::string>("clear")) << signature(r);
    for (std::size_t v = 0; v < r.variables.size(); ++v) {
      const RuleVariable& variable = r.variables[v];
      bool acted_on = std::find(r.action_args.begin(), r.action_args.end(), v) != r.action_args.end();
      // The object of interest is never tested by category: that is what
      // lets the plate's rules serve the fork.
      if (variable.object_of_interest || !acted_on) {
        EXPECT_FALSE(variable.category.has_value()) << signature(r) << " " << variable.name;
      } else {
        EXPECT_TRUE(variable.category.has_value()) << signature(r) << " " << variable.name;
      }
    }
  }
  EXPECT_THAT(signature(rules[3]), HasSubstr("open(?r) <- subtask=clear interest(?o) category(?r)=dishwasher "));
  EXPECT_THAT(signature(rules[2]), HasSubstr("pick-up(?o, ?s) <- subtask=clear interest(?o) category(?s)=table "));
}

TEST_F(Learning, FullTestsNoSubtaskAndNoCategory) {
  for (const Rule& r : learn(world_, ceramic_plate_episode(world_), Generalization::kFull)) {
    EXPECT_FALSE(r.subtask.has_value()) << signature(r);
    for (const RuleVariable& v : r.variables) EXPECT_FALSE(v.category.has_value()) << signature(r);
  }
}

TEST_F(Learning, PaperAndFullDifferOnlyInTheirTests) {
  std::vector<Rule> paper = learn(world_, ceramic_plate_episode(world_), Generalization::kPaper);
  std::vector<Rule> full = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  ASSERT_EQ(paper.size(), full.size());
  for (std::size_t i = 0; i < paper.size(); ++i) {
    EXPECT_EQ(paper[i].goal, full[i].goal);
    EXPECT_EQ(paper[i].conditions, full[i].conditions);
    EXPECT_EQ(paper[i].action, full[i].action);
    EXPECT_EQ(paper[i].action_args, full[i].action_args);
    EXPECT_EQ(paper[i].steps_to_goal, full[i].steps_to_goal);
  }
}

TEST_F(Learning, RulesRecordWhereTheyCameFrom) {
  std::vector<Rule> rules = learn(world_, ceramic_plate_episode(world_), Generalization::kFull);
  ASSERT_EQ(rules.size(), 4u);
  EXPECT_EQ(rules[3].provenance.object, "ceramic-plate1 (ceramic-plate)");
  EXPECT_EQ(rules[3].provenance.source, "instructor: \"(open dishwasher1)\"");
  EXPECT_EQ(rules[0].provenance.source, "instructor: \"(close dishwasher1)\"");
}

TEST_F(Learning, GoalWithoutADoorNeedsNoOpenOrClose) {
  Episode episode = make_episode(world_, world_.state, "paper-plate1", "(in paper-plate1 garbage1)", "clear",
                                 {"(pick-up paper-plate1 table1)", "(put-in paper-plate1 garbage1)"});
  std::vector<Rule> rules = learn(world_, episode, Generalization::kFull);
  EXPECT_THAT(signatures(world_, rules),
              ElementsAre("put-in(?o, ?r) <- interest(?o) goal{(in ?o ?r)} state{(holding ?o) (not (closed ?r)) "
                          "(receptacle ?r)} steps=1",
                          "pick-up(?o, ?s) <- interest(?o) goal{(in ?o ?r)} state{(on ?o ?s) (handempty) "
                          "(not (closed ?r)) (grabbable ?o) (receptacle ?r) (surface ?s)} steps=2"));
}

TEST_F(Learning, AnEpisodeThatAlreadyHoldsItsGoalTeachesNothing) {
  State done = after(world_, world_.state,
                     {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)", "(put-in ceramic-plate1 dishwasher1)",
                      "(close dishwasher1)"});
  Episode episode = make_episode(world_, done, "ceramic-plate1", kCeramicPlateGoal, "clear", {});
  EXPECT_TRUE(learn(world_, episode, Generalization::kFull).empty());
}

TEST_F(Learning, RulesAreDeterministic) {
  EXPECT_EQ(learn(world_, ceramic_plate_episode(world_), Generalization::kPaper),
            learn(world_, ceramic_plate_episode(world_), Generalization::kPaper));
}

using LearningDeathTest = Learning;

TEST_F(LearningDeathTest, AnEpisodeThatMissesItsGoalIsABug) {
  Episode episode = make_episode(world_, world_.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                                 {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)"});
  EXPECT_DEATH(learn(world_, episode, Generalization::kFull), "missed its goal");
}

}  // namespace
}  // namespace apprentice
