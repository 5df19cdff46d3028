// The agent's use of LLM goals in whole runs against the fake server
// (issue 13, items 1, 2 and 4): the instructor hears the repaired goal in
// English; after a "no" or an unusable answer the model is asked again with
// the rejected answers in the prompt; and --offer-ungrounded brings back the
// paper's way of offering what the agent cannot ground.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "experiment_fixtures.h"
#include "fake_llm_server.h"

namespace apprentice {
namespace {

using testing::experiment_options;
using testing::factory;
using testing::FakeLlmServer;
using testing::load_or_die;
using testing::ServerMode;
using testing::source_path;
using ::testing::HasSubstr;
using ::testing::Not;

const char* const kKitchen = "data/scenarios/tidy-kitchen.yaml";

int occurrences(const std::string& text, const std::string& part) {
  int n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(LlmGoals, TheInstructorHearsTheRepairedGoalInEnglish) {
  Scenario scenario = load_or_die(source_path(kKitchen));
  FakeLlmServer server(ServerMode::kModel,
                       {{"soda-can", {"The goal is that the X is in the recycling bin and the recycling bin is closed"}},
                        {"ketchup", {"The goal is that the X is in the fridge"}}});
  ConditionResult result = testing::run(scenario, "inst+search4+llm", experiment_options(factory("openai:" + server.url())));
  EXPECT_EQ(result.completion_rate, 100.0);
  // The bin has no lid: the closing is left out, and the rest is right.
  EXPECT_THAT(result.transcript, HasSubstr("[LM] For a soda can on the table, is the goal that the soda can is in the "
                                           "recycling bin?\nInstructor: yes.\n"));
  // The fridge has a door: "close what you opened" completes the goal.
  EXPECT_THAT(result.transcript, HasSubstr("[LM] For a ketchup on the table, is the goal that the ketchup is in the "
                                           "fridge and the fridge is closed?\nInstructor: yes.\n"));
  EXPECT_EQ(result.counts.yes, 2);
  EXPECT_EQ(result.counts.yes_no, 2);  // the fallback statements ground to nothing: never offered
}

TEST(LlmGoals, AfterANoTheModelIsAskedAgainWithTheRejectedAnswer) {
  Scenario scenario = load_or_die(source_path(kKitchen));
  FakeLlmServer server(ServerMode::kModel, {{"ketchup", {"The goal is that the X is in the cupboard"}}},
                       {"The goal is that the X is on the moon"},
                       {{"ketchup", {"The goal is that the X is in the fridge and the fridge is closed"}}});
  ConditionResult result = testing::run(scenario, "inst+search4+llm", experiment_options(factory("openai:" + server.url())));
  EXPECT_EQ(result.completion_rate, 100.0);
  EXPECT_THAT(result.transcript,
              HasSubstr("[LM] For a ketchup on the table, is the goal that the ketchup is in the cupboard and the "
                        "cupboard is closed?\nInstructor: no.\n"
                        "Agent: [LM] For a ketchup on the table, is the goal that the ketchup is in the fridge and the "
                        "fridge is closed?\nInstructor: yes.\n"));
  bool reprompted = false;
  for (const std::string& prompt : server.goal_prompts())
    if (prompt.find("Aware of ketchup on table.\nNot: the ketchup is in the cupboard.\n(RESULT)") != std::string::npos)
      reprompted = true;
  EXPECT_TRUE(reprompted);
  // Objects the model knows nothing usable about were re-asked once, with
  // what it said listed, then described by the instructor.
  EXPECT_GT(occurrences(result.transcript, " go?\nInstructor: "), 0);  // "Where should ... go?"
}

TEST(LlmGoals, WithoutAnInstructorAnUnusableAnswerIsFollowedByARePrompt) {
  Scenario scenario = load_or_die(source_path(kKitchen));
  FakeLlmServer server(ServerMode::kModel, {{"milk", {"The goal is that the X is in the attic"}}},
                       {"The goal is that the X is on the moon"},
                       {{"milk", {"The goal is that the X is in the fridge and the fridge is closed"}}});
  ConditionResult result = testing::run(scenario, "search4+llm", experiment_options(factory("openai:" + server.url())));
  ASSERT_TRUE(result.relevance.has_value());
  bool milk_adopted = false;
  for (const ObjectReport& object : result.agent.objects)
    if (object.object.rfind("milk", 0) == 0 && object.goal_source == GoalSource::kLlm && object.achieved) milk_adopted = true;
  EXPECT_TRUE(milk_adopted);
  // Turned off, the unusable answer fails the object, as before.
  ExperimentOptions no_reprompt = experiment_options(factory("openai:" + server.url()));
  no_reprompt.goal_repair.reprompt = false;
  ConditionResult once = testing::run(scenario, "search4+llm", no_reprompt);
  for (const ObjectReport& object : once.agent.objects)
    if (object.object.rfind("milk", 0) == 0) {
      EXPECT_NE(object.goal_source, GoalSource::kLlm);
    }
}

TEST(LlmGoals, OfferingUngroundedResponsesAsThePaperDidCanBeMeasured) {
  Scenario scenario = load_or_die(source_path(kKitchen));
  FakeLlmServer server(ServerMode::kModel, {}, {"The goal is that the X is on the moon"});
  ExperimentOptions paper = experiment_options(factory("openai:" + server.url()));
  paper.goal_repair = GoalRepairOptions::none();
  paper.offer_ungrounded = true;
  paper.goal_responses = 3;
  ConditionResult offered = testing::run(scenario, "inst+search4+llm", paper);
  EXPECT_THAT(offered.transcript,
              HasSubstr("[LM] For a ketchup on the table, is the goal that the ketchup is on the moon?\nInstructor: no.\n"));
  EXPECT_EQ(offered.counts.yes, 0);
  EXPECT_GT(offered.counts.yes_no, 0);
  EXPECT_EQ(offered.relevance, std::optional<double>(0.0));
  ConditionResult ours = testing::run(scenario, "inst+search4+llm", experiment_options(factory("openai:" + server.url())));
  EXPECT_EQ(ours.counts.yes_no, 0);  // never offered what does not ground
  EXPECT_THAT(ours.transcript, Not(HasSubstr("on the moon")));
}

}  // namespace
}  // namespace apprentice
