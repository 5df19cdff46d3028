// The agent's and the instructor's sentences, in the paper's words; each
// parses and grounds back to what it says.
#include <vector>

#include <gtest/gtest.h>

#include "language/generation.h"
#include "language_fixtures.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::id;
using testing::world35;

Goal goal(std::string_view text) {
  auto parsed = parse_goal(*world35().domain, *world35().universe, text);
  EXPECT_TRUE(parsed.has_value()) << text;
  return parsed ? *parsed : Goal();
}

Action action(std::string_view text) {
  auto parsed = parse_action(*world35().domain, *world35().universe, text);
  EXPECT_TRUE(parsed.has_value()) << text;
  return parsed ? *parsed : Action();
}

TEST(Generation, TheAgentsQuestions) {
  EXPECT_EQ(say_next_goal_request("clear"), "What is the next goal or subtask of clear?");
  EXPECT_EQ(say_next_action_request("clear"), "What do I do next for clear?");
  EXPECT_EQ(say_goal_question(world35(), id("ceramic-plate1"),
                              "the goal is that the ceramic-plate is in the cupboard and the cupboard is closed"),
            "[LM] For a ceramic plate on the table, is the goal that the ceramic plate is in the cupboard and the "
            "cupboard is closed?");
  EXPECT_EQ(say_goal_question(world35(), id("glass-tumbler2"), goal("(and (in glass-tumbler2 cupboard1) (closed cupboard1))"),
                              false),
            "For a glass tumbler in the dish rack, is the goal that the glass tumbler is in the cupboard and the "
            "cupboard is closed?");
  EXPECT_EQ(say_goal_question(world35(), id("apple-juice1"), "The goal is that the apple-juice is in the fridge."),
            "[LM] For an apple juice on the table, is the goal that the apple juice is in the fridge?");
  EXPECT_EQ(say_action_question(world35(), id("ceramic-plate1"), "Pick up ceramic-plate"),
            "[LM] For the ceramic plate, should I 'Pick up ceramic plate'?");
  EXPECT_EQ(say_action_question(world35(), id("ceramic-plate1"), "Open dishwasher.", false),
            "For the ceramic plate, should I 'Open dishwasher'?");
}

TEST(Generation, ActionsInTheInstructorsWords) {
  EXPECT_EQ(describe_action(world35(), action("(open fridge1)")), "Open the fridge.");
  EXPECT_EQ(describe_action(world35(), action("(pick-up ketchup1 table1)")), "Pick up the ketchup.");
  EXPECT_EQ(describe_action(world35(), action("(pick-up-from mug2 dish-rack1)")), "Pick up the mug.");
  EXPECT_EQ(describe_action(world35(), action("(put-in ketchup1 fridge1)")), "Put the ketchup in the fridge.");
  EXPECT_EQ(describe_action(world35(), action("(put-in soda-can1 recycling-bin1)")),
            "Put the soda-can in the recycling bin.");
  EXPECT_EQ(describe_action(world35(), action("(put-on mug1 counter1)")), "Put the mug on the counter.");
  EXPECT_EQ(describe_action(world35(), action("(close fridge1)")), "Close the fridge.");
  std::vector<Action> plan{action("(open fridge1)"), action("(pick-up ketchup1 table1)")};
  EXPECT_EQ(describe_plan(world35(), plan), "Open the fridge. Pick up the ketchup.");
}

TEST(Generation, GoalsInEnglish) {
  Goal g = goal("(and (closed fridge1) (in ketchup1 fridge1))");
  EXPECT_EQ(describe_goal(world35(), g), "the ketchup is in the fridge and the fridge is closed");
  EXPECT_EQ(describe_goal_instruction(world35(), id("ketchup1"), g),
            "If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.");
  EXPECT_EQ(describe_goal_instruction(world35(), id("apple-core1"), goal("(in apple-core1 garbage1)")),
            "If the object is an apple-core then the goal is that the object is in the garbage.");
  EXPECT_EQ(describe_goal(world35(), goal("(and (in mug1 dishwasher1) (not (closed dishwasher1)))")),
            "the mug is in the dishwasher and the dishwasher is open");
}

TEST(Generation, TaskStructure) {
  EXPECT_EQ(say_task_name("tidy kitchen"), "Tidy kitchen.");
  EXPECT_EQ(say_repeat_while(world35(), id("table1")), "Repeat the following tasks while an object is on the table.");
  EXPECT_EQ(say_repeat_while(world35(), id("dish-rack1")),
            "Repeat the following tasks while an object is in the dish rack.");
  EXPECT_EQ(say_subtask("clear", world35(), id("table1")), "Clear an object that is on the table.");
  EXPECT_EQ(say_subtask("unload", world35(), id("dish-rack1")), "Unload an object that is in the dish rack.");
  EXPECT_EQ(say_done(), "You are done.");
  EXPECT_EQ(say_repeat(), "Repeat.");
  EXPECT_EQ(say_answer(true), "yes.");
  EXPECT_EQ(say_answer(false), "no.");
  EXPECT_EQ(article_for("apple-juice"), "an");
  EXPECT_EQ(article_for("ketchup"), "a");
  // By sound, not spelling: "a unicorn", "a used cup", "a euro coin", "an hour glass".
  EXPECT_EQ(article_for("unicorn"), "a");
  EXPECT_EQ(article_for("used-cup"), "a");
  EXPECT_EQ(article_for("euro-coin"), "a");
  EXPECT_EQ(article_for("hourglass"), "an");
  EXPECT_EQ(article_for("umbrella"), "an");
}

// What the generators say parses and grounds back to what they were given.
TEST(Generation, RoundTripsThroughTheGrounder) {
  const World& world = world35();
  for (std::string_view text : {"(open fridge1)", "(close drawer1)", "(pick-up plate1 counter1)",
                                "(pick-up-from paring-knife1 dish-rack1)", "(put-in newspaper1 recycling-bin1)",
                                "(put-on coffee-grinder1 table1)", "(put-in half-and-half1 fridge1)"}) {
    Action a = action(text);
    std::optional<ObjectId> object = a.arguments().front();
    Interpretation in = grounder().interpret(describe_action(world, a), world, object);
    EXPECT_EQ(format_grounding(world, in.result), "action " + std::string(text)) << describe_action(world, a);
  }
  for (std::string_view text : {"(and (in ketchup1 fridge1) (closed fridge1))", "(in pepsi-can1 recycling-bin1)",
                                "(and (in crackers1 pantry1) (closed pantry1))", "(on mug2 counter1)"}) {
    Goal g = goal(text);
    ObjectId object = g.literals.back().fact.args[0];
    for (const Literal& l : g.literals)
      if (l.fact.arity == 2) object = l.fact.args[0];
    Interpretation in = grounder().interpret(describe_goal_instruction(world, object, g), world, object);
    EXPECT_EQ(format_grounding(world, in.result), "goal " + std::string(text));
    in = grounder().interpret("the goal is that " + describe_goal(world, g), world, object);
    EXPECT_EQ(format_grounding(world, in.result), "goal " + std::string(text));
  }
}

}  // namespace
}  // namespace apprentice::language
