// The simulated instructor speaks exactly as the STARS tidy-kitchen
// instructor script does, answers next-action questions with the first
// step of a shortest plan, and says yes to a proposal exactly when it is
// what the instructor wants (a goal, by meaning, however it is worded; an
// action, when it lies on a shortest plan).
#include "instructor/simulated_instructor.h"

#include <fstream>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/understanding.h"
#include "instructor_fixtures.h"
#include "util/text.h"

namespace apprentice {
namespace {

using testing::load_or_die;
using testing::object;
using testing::shared_path;
using testing::source_path;

Question about(QuestionKind kind, std::string subtask, std::optional<ObjectId> object = std::nullopt) {
  Question q;
  q.kind = kind;
  q.text = "(question text does not matter)";
  q.task = "tidy kitchen";
  q.subtask = std::move(subtask);
  q.object = object;
  return q;
}

std::string reply(SimulatedInstructor& instructor, const Question& q, const World& world) {
  auto answer = instructor.answer(q, world);
  EXPECT_TRUE(answer.has_value()) << (answer ? "" : answer.error().describe());
  return answer.value_or("");
}

Action parse(const World& world, std::string_view text) {
  auto action = parse_action(*world.domain, *world.universe, text);
  EXPECT_TRUE(action.has_value()) << text;
  return action.value_or(Action());
}

class SimulatedInstructorTest : public ::testing::Test {
 protected:
  Scenario kitchen_ = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  Scenario kitchen35_ = load_or_die(source_path("data/scenarios/tidy-kitchen-35.yaml"));
};

// --- The task structure ------------------------------------------------------

TEST_F(SimulatedInstructorTest, NamesTheTask) {
  SimulatedInstructor instructor(kitchen_);
  EXPECT_EQ(reply(instructor, about(QuestionKind::kTaskName, ""), kitchen_.world), "Tidy kitchen.");
}

TEST_F(SimulatedInstructorTest, TeachesTheSubtasksInOrderAsTheScriptDoes) {
  SimulatedInstructor instructor(kitchen_);
  std::vector<std::string> said;
  for (int i = 0; i < 11; ++i) said.push_back(reply(instructor, about(QuestionKind::kTaskStep, ""), kitchen_.world));
  EXPECT_THAT(said, ::testing::ElementsAre("Repeat the following tasks while an object is on the table.",
                                           "Clear an object that is on the table.",
                                           "Repeat.",
                                           "Repeat the following tasks while an object is on the counter.",
                                           "Store an object that is on the counter.",
                                           "Repeat.",
                                           "Repeat the following tasks while an object is in the dish rack.",
                                           "Unload an object that is in the dish rack.",
                                           "Repeat.",
                                           "You are done.",
                                           "You are done."));
}

TEST_F(SimulatedInstructorTest, SaysTheSubtaskIsDoneWhenAskedAboutNoObject) {
  SimulatedInstructor instructor(kitchen_);
  EXPECT_EQ(reply(instructor, about(QuestionKind::kSubtaskStep, "clear"), kitchen_.world), "You are done.");
}

// --- Goal descriptions ---------------------------------------------------------

// The goal the simulated instructor gives for every object of the 35-object
// kitchen, keyed by subtask and category.
std::map<std::pair<std::string, std::string>, std::string> goal_descriptions(const Scenario& scenario) {
  SimulatedInstructor instructor(scenario);
  std::map<std::pair<std::string, std::string>, std::string> out;
  for (ObjectId o : scenario.world.universe->of_kind(ObjectKind::kItem)) {
    const Subtask* subtask = scenario.subtask_of(o);
    if (subtask == nullptr) continue;
    auto answer = instructor.answer(about(QuestionKind::kSubtaskStep, subtask->verb, o), scenario.world);
    EXPECT_TRUE(answer.has_value());
    out[{subtask->verb, scenario.world.universe->info(o).category}] = answer.value_or("");
  }
  return out;
}

TEST_F(SimulatedInstructorTest, GoalDescriptionsAreWordedAsInTheScript) {
  // A few lines of ../shared/data/stars-tidy-kitchen/instructor_script.txt,
  // checked in so that this test means something without ../shared.
  auto said = goal_descriptions(kitchen35_);
  ASSERT_EQ(said.size(), 35u);
  EXPECT_EQ((said[{"clear", "ketchup"}]),
            "If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.");
  EXPECT_EQ((said[{"clear", "apple-juice"}]),
            "If the object is an apple-juice then the goal is that the object is in the fridge and the fridge is "
            "closed.");
  EXPECT_EQ((said[{"clear", "pepsi-can"}]),
            "If the object is a pepsi-can then the goal is that the object is in the recycling bin.");
  EXPECT_EQ((said[{"store", "apple-core"}]),
            "If the object is an apple-core then the goal is that the object is in the garbage.");
  EXPECT_EQ((said[{"store", "box-of-aluminum-foil"}]),
            "If the object is a box-of-aluminum-foil then the goal is that the object is in the pantry and the pantry "
            "is closed.");
  EXPECT_EQ((said[{"store", "steak-knife"}]),
            "If the object is a steak-knife then the goal is that the object is in the dishwasher and the dishwasher "
            "is closed.");
  EXPECT_EQ((said[{"unload", "steak-knife"}]),
            "If the object is a steak-knife then the goal is that the object is in the drawer and the drawer is "
            "closed.");
  EXPECT_EQ((said[{"unload", "ceramic-bowl"}]),
            "If the object is a ceramic-bowl then the goal is that the object is in the cupboard and the cupboard is "
            "closed.");
}

// The script's lines: the goal descriptions of each subtask section, and
// the task-structure lines.
struct Script {
  std::map<std::pair<std::string, std::string>, std::string> goals;  // (subtask, category) -> line
  std::set<std::string> structure;
  int goal_lines = 0;
};

Script read_script(const std::filesystem::path& path) {
  Script script;
  std::ifstream in(path);
  std::string subtask;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the file has CRLF line ends
    if (number <= 2) continue;  // "yes." and "no.": answers for yes/no questions
    std::vector<std::string> words = split_words(line);
    if (words.empty()) continue;
    if (words.size() > 2 && words[1] == "an" && words[2] == "object") subtask = to_lower(words[0]);
    if (starts_with_ignoring_case(line, "If the object is ")) {
      ++script.goal_lines;
      std::string category = words.at(5);  // "If the object is a ketchup ..."
      script.goals[{subtask, category}] = line;
    } else {
      script.structure.insert(line);
    }
  }
  return script;
}

TEST_F(SimulatedInstructorTest, GoalDescriptionsAreTheScriptsLinesForAll35Objects) {
  const auto path = shared_path("data/stars-tidy-kitchen/instructor_script.txt");
  APPRENTICE_REQUIRE_SHARED(path);
  Script script = read_script(path);
  ASSERT_EQ(script.goal_lines, 35);
  ASSERT_EQ(script.goals.size(), 35u);
  auto said = goal_descriptions(kitchen35_);
  EXPECT_EQ(said, script.goals);
}

TEST_F(SimulatedInstructorTest, TaskStructureLinesAreTheScriptsLines) {
  const auto path = shared_path("data/stars-tidy-kitchen/instructor_script.txt");
  APPRENTICE_REQUIRE_SHARED(path);
  Script script = read_script(path);
  SimulatedInstructor instructor(kitchen35_);
  std::set<std::string> said{reply(instructor, about(QuestionKind::kTaskName, ""), kitchen35_.world)};
  for (int i = 0; i < 10; ++i) said.insert(reply(instructor, about(QuestionKind::kTaskStep, ""), kitchen35_.world));
  EXPECT_EQ(said, script.structure);
}

TEST_F(SimulatedInstructorTest, SaysDoneForAnObjectWhoseGoalAlreadyHolds) {
  World world = kitchen_.world;
  ObjectId ketchup = object(world, "ketchup1");
  for (const char* step : {"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)"})
    world.state = apply(*world.domain, world.state, parse(world, step));
  SimulatedInstructor instructor(kitchen_);
  // The fridge is still open: the goal does not hold yet.
  EXPECT_THAT(reply(instructor, about(QuestionKind::kSubtaskStep, "clear", ketchup), world),
              ::testing::StartsWith("If the object is a ketchup"));
  world.state = apply(*world.domain, world.state, parse(world, "(close fridge1)"));
  EXPECT_EQ(reply(instructor, about(QuestionKind::kSubtaskStep, "clear", ketchup), world), "You are done.");
}

// --- Next actions ----------------------------------------------------------------

TEST_F(SimulatedInstructorTest, NextActionIsTheFirstStepOfAShortestPlan) {
  SimulatedInstructor instructor(kitchen_);
  World world = kitchen_.world;
  ObjectId ketchup = object(world, "ketchup1");
  // The robot has one arm: it opens the fridge before picking up the ketchup.
  EXPECT_EQ(reply(instructor, about(QuestionKind::kNextAction, "clear", ketchup), world), "Open the fridge.");
  world.state = apply(*world.domain, world.state, parse(world, "(open fridge1)"));
  EXPECT_EQ(reply(instructor, about(QuestionKind::kNextAction, "clear", ketchup), world), "Pick up the ketchup.");
  world.state = apply(*world.domain, world.state, parse(world, "(pick-up ketchup1 table1)"));
  EXPECT_EQ(reply(instructor, about(QuestionKind::kNextAction, "clear", ketchup), world),
            "Put the ketchup in the fridge.");
  world.state = apply(*world.domain, world.state, parse(world, "(put-in ketchup1 fridge1)"));
  EXPECT_EQ(reply(instructor, about(QuestionKind::kNextAction, "clear", ketchup), world), "Close the fridge.");
  // Nothing goes into the garbage through a door.
  EXPECT_EQ(reply(instructor, about(QuestionKind::kNextAction, "clear", object(world, "paper-plate1")), world),
            "Pick up the paper-plate.");
}

TEST_F(SimulatedInstructorTest, NextActionPutsDownWhatTheRobotHoldsBeforeOpeningADoor) {
  SimulatedInstructor instructor(kitchen_);
  World world = kitchen_.world;
  world.state = apply(*world.domain, world.state, parse(world, "(pick-up milk1 table1)"));
  std::string said = reply(instructor, about(QuestionKind::kNextAction, "clear", object(world, "ketchup1")), world);
  EXPECT_THAT(said, ::testing::StartsWith("Put the milk ")) << said;
}

TEST(ShortestPlanLength, CountsTheStepsOrNothingBeyondTheDepth) {
  Scenario kitchen = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  const World& world = kitchen.world;
  auto goal = kitchen.intended_goal("clear", object(world, "ketchup1"));
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(shortest_plan_length(world, world.state, *goal, 8), 4);
  EXPECT_EQ(shortest_plan_length(world, world.state, *goal, 3), std::nullopt);
}

// --- Yes and no ----------------------------------------------------------------------

class ConfirmationTest : public SimulatedInstructorTest {
 protected:
  // Grounds `statement` about `id` as the agent would, and asks.
  std::string confirm_goal(std::string_view statement, std::string_view id, std::string subtask = "clear") {
    const World& world = kitchen_.world;
    ObjectId o = object(world, id);
    GoalMeaning meaning = understanding_.goal(world, statement, o);
    EXPECT_TRUE(meaning.goal.has_value()) << statement << ": " << meaning.failure;
    Question q = about(QuestionKind::kConfirmGoal, std::move(subtask), o);
    q.goal = meaning.goal;
    return reply(instructor_, q, world);
  }
  std::string confirm_action(std::string_view command, std::string_view id, const World& world) {
    ObjectId o = object(world, id);
    ActionMeaning meaning = understanding_.action(world, command, o);
    EXPECT_TRUE(meaning.action.has_value()) << command << ": " << meaning.failure;
    Question q = about(QuestionKind::kConfirmAction, "clear", o);
    q.action = meaning.action;
    return reply(instructor_, q, world);
  }

  Understanding understanding_;
  SimulatedInstructor instructor_{kitchen_};
};

TEST_F(ConfirmationTest, YesForTheIntendedGoalHoweverItIsWorded) {
  EXPECT_EQ(confirm_goal("the goal is that the ketchup is in the fridge and the fridge is closed", "ketchup1"), "yes.");
  EXPECT_EQ(confirm_goal("the goal is that the fridge is closed and the ketchup is in the fridge", "ketchup1"), "yes.");
  EXPECT_EQ(confirm_goal("The goal is that the ketchup is in the fridge and the fridge is closed.", "ketchup1"),
            "yes.");
  EXPECT_EQ(confirm_goal("If the object is a ketchup then the goal is that the object is in the fridge and the "
                         "fridge is closed.",
                         "ketchup1"),
            "yes.");
  EXPECT_EQ(confirm_goal("the goal is that the paper-plate is in the garbage", "paper-plate1"), "yes.");
}

TEST_F(ConfirmationTest, NoForAnotherReceptacleOrAnIncompleteGoal) {
  EXPECT_EQ(confirm_goal("the goal is that the ketchup is in the pantry and the pantry is closed", "ketchup1"), "no.");
  EXPECT_EQ(confirm_goal("the goal is that the ketchup is in the fridge", "ketchup1"), "no.");
  EXPECT_EQ(confirm_goal("the goal is that the paper-plate is in the recycling bin", "paper-plate1"), "no.");
}

TEST_F(ConfirmationTest, TheSameCategoryCanWantAnotherPlaceInAnotherSubtask) {
  // A mug on the counter goes to the dishwasher; one in the dish rack to the cupboard.
  EXPECT_EQ(confirm_goal("the goal is that the mug is in the dishwasher and the dishwasher is closed", "mug1", "store"),
            "yes.");
  EXPECT_EQ(confirm_goal("the goal is that the mug is in the cupboard and the cupboard is closed", "mug1", "store"),
            "no.");
}

// A question about several things at once ("and the milk too?"): "yes"
// only when every one of them goes where the goal puts the object asked
// about, by the same goal.
TEST_F(ConfirmationTest, ThingsAskedTogetherAreYesOnlyWhenEachGoesThere) {
  const World& world = kitchen_.world;
  const ObjectId ketchup = object(world, "ketchup1");
  GoalMeaning meaning = understanding_.goal(world, "the goal is that the ketchup is in the fridge and the fridge is closed", ketchup);
  ASSERT_TRUE(meaning.goal.has_value()) << meaning.failure;
  Question q = about(QuestionKind::kConfirmGoal, "clear", ketchup);
  q.goal = meaning.goal;
  q.together = {object(world, "milk1")};
  EXPECT_EQ(reply(instructor_, q, world), "yes.");
  q.together.push_back(object(world, "paper-plate1"));  // goes in the garbage
  EXPECT_EQ(reply(instructor_, q, world), "no.");
  q.together = {object(world, "paper-plate1")};
  EXPECT_EQ(reply(instructor_, q, world), "no.");
}

TEST_F(ConfirmationTest, NoForAGoalQuestionWithoutAGoal) {
  Question q = about(QuestionKind::kConfirmGoal, "clear", object(kitchen_.world, "ketchup1"));
  EXPECT_EQ(reply(instructor_, q, kitchen_.world), "no.");
}

TEST_F(ConfirmationTest, YesForAnActionOnAShortestPlanAndNoOtherwise) {
  World world = kitchen_.world;
  EXPECT_EQ(confirm_action("Open the fridge.", "ketchup1", world), "yes.");
  EXPECT_EQ(confirm_action("Open fridge", "ketchup1", world), "yes.");
  // Picking up first is possible, but the ketchup would have to be put down
  // again to open the door: not on a shortest plan.
  EXPECT_EQ(confirm_action("Pick up the ketchup.", "ketchup1", world), "no.");
  EXPECT_EQ(confirm_action("Open the pantry.", "ketchup1", world), "no.");
  // Not applicable: the robot holds nothing.
  EXPECT_EQ(confirm_action("Put the ketchup in the fridge.", "ketchup1", world), "no.");
  world.state = apply(*world.domain, world.state, parse(world, "(open fridge1)"));
  EXPECT_EQ(confirm_action("Pick up the ketchup.", "ketchup1", world), "yes.");
  EXPECT_EQ(confirm_action("Close the fridge.", "ketchup1", world), "no.");
  // For the paper-plate picking up first is the shortest plan.
  EXPECT_EQ(confirm_action("Pick up the paper-plate.", "paper-plate1", kitchen_.world), "yes.");
}

}  // namespace
}  // namespace apprentice
