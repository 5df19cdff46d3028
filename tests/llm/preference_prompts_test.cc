// A person's preferences asked of an LLM (llm/preference_prompts.h): our
// prompts, the answers read back in the world's words, and the recorded
// TidyBot answers served by content (llm/placement_corpus.h).
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "common/paths.h"
#include "llm/cassette.h"
#include "llm/factory.h"
#include "llm/placement_corpus.h"
#include "llm/preference_prompts.h"

namespace apprentice::llm {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::Pair;

PreferencePrompts shipped_prompts() {
  auto prompts = PreferencePrompts::load(apprentice::testing::source_path("data/prompts"));
  EXPECT_TRUE(prompts) << prompts.error().describe();
  return std::move(*prompts);
}

TEST(PreferencePrompts, TheSummaryPromptHoldsThePlacesAndTheExamples) {
  CompletionRequest request = shipped_prompts().summary_request({"basket", "drawer"}, {{"dress", "basket"}, {"toy block", "drawer"}});
  EXPECT_THAT(request.prompt, HasSubstr("Places: basket, drawer.\nExamples: dress -> basket; toy block -> drawer.\nRule:"));
  EXPECT_TRUE(request.prompt.ends_with("Rule:"));
  EXPECT_THAT(request.stop, ElementsAre("\n"));
  EXPECT_EQ(request.about.kind, QueryKind::kSummary);
  EXPECT_THAT(request.about.receptacles, ElementsAre("basket", "drawer"));
  EXPECT_THAT(request.about.examples, ElementsAre(Pair("dress", "basket"), Pair("toy block", "drawer")));
}

TEST(PreferencePrompts, APlacementIsAskedByTheRuleByTheExamplesOrByCommonSense) {
  const PreferencePrompts prompts = shipped_prompts();
  const std::vector<ThingPlace> examples{{"dress", "basket"}};
  CompletionRequest by_rule = prompts.placement_request({"basket", "drawer"}, "Put clothes in the basket.", examples,
                                                        {"sweater", "rubiks cube"});
  EXPECT_THAT(by_rule.prompt, HasSubstr("Places: basket, drawer.\nRule: Put clothes in the basket.\nThings: sweater, rubiks cube."));
  EXPECT_TRUE(by_rule.about.examples.empty()) << "by a rule, the examples are not part of the query";
  EXPECT_EQ(by_rule.about.summary, "Put clothes in the basket.");
  CompletionRequest by_examples = prompts.placement_request({"basket", "drawer"}, "", examples, {"sweater"});
  EXPECT_THAT(by_examples.prompt, HasSubstr("\nExamples: dress -> basket.\nThings: sweater."));
  CompletionRequest common = prompts.placement_request({"basket", "drawer"}, "", {}, {"sweater"});
  EXPECT_THAT(common.prompt, HasSubstr("Places: basket, drawer.\n\nThings: sweater."));
  EXPECT_EQ(common.about.kind, QueryKind::kPlacement);
  EXPECT_THAT(common.about.objects, ElementsAre("sweater"));
}

TEST(PreferencePrompts, ATemplateWithAnUnknownOrMissingPlaceholderIsRefused) {
  const auto dir = std::filesystem::temp_directory_path() / ("apprentice_prefs_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const char* name, const char* text) { std::ofstream(dir / name) << text; };
  write("summary.txt", "Places: {receptacles}. Examples: {examples}. {colour}");
  write("placement.txt", "{receptacles} {knowledge} {objects}");
  auto unknown = PreferencePrompts::load(dir);
  ASSERT_FALSE(unknown);
  EXPECT_THAT(unknown.error().message, HasSubstr("unknown placeholder {colour}"));
  write("summary.txt", "Places: {receptacles}.");
  auto missing = PreferencePrompts::load(dir);
  ASSERT_FALSE(missing);
  EXPECT_THAT(missing.error().message, HasSubstr("needs {examples}"));
  std::filesystem::remove_all(dir);
}

TEST(PreferenceAnswers, TheRuleIsTheFirstLine) {
  EXPECT_EQ(read_summary(" Put clothes in the basket.\nPut toys in the drawer."), "Put clothes in the basket.");
  EXPECT_EQ(read_summary("\n\nRule: Put toys in the drawer."), "Put toys in the drawer.");
  EXPECT_EQ(read_summary(""), "");
}

TEST(PreferenceAnswers, PlacementsAreReadInEveryFormAndMatchedToTheWorldsNames) {
  const std::vector<std::string> objects{"sweater", "rubiks cube", "toy hammer", "play doh", "pillow"};
  const std::vector<std::string> places{"basket", "top drawer", "bottom drawer"};
  auto placed = read_placements(
      "sweater -> basket\npick_and_place(\"Rubik's cube\", \"top drawer\")\nToy hammer: bottom drawer\n"
      "Put the Play-Doh in the top drawer.\npillow 2 -> basket\nsweater -> top drawer\nteapot -> basket\n"
      "rubiks cube -> attic",
      objects, places);
  EXPECT_THAT(placed, ElementsAre(Pair("sweater", "basket"), Pair("rubiks cube", "top drawer"),
                                  Pair("toy hammer", "bottom drawer"), Pair("play doh", "top drawer"),
                                  Pair("pillow", "basket")));
  EXPECT_EQ(name_key("The Rubik's Cube"), "rubiks cube");
  EXPECT_EQ(name_key("Play-Doh"), "play doh");
  EXPECT_EQ(name_key("pillow 2"), "pillow");
  EXPECT_EQ(name_key("bin 1", NameOf::kPlace), "bin 1");
  EXPECT_THAT(read_placements("fork -> bin 2\nspoon -> Bin 1", {"fork", "spoon"}, {"bin 1", "bin 2"}),
              ElementsAre(Pair("fork", "bin 2"), Pair("spoon", "bin 1")));
}

class PlacementCorpus : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = std::filesystem::temp_directory_path() / ("apprentice_placements_" + std::to_string(::getpid()) + ".jsonl");
    std::ofstream out(path_);
    // Answers written here, in the TidyBot corpus's keys.
    out << R"({"scenario": 1, "method": "summarization", "step": "summary", "receptacles": ["hamper", "toy chest"], "examples": [["polo shirt", "hamper"], ["wooden block", "toy chest"]], "completion": " Put shirts in the hamper and blocks in the toy chest.", "summary": "Put shirts in the hamper and blocks in the toy chest."})" "\n"
        << R"({"scenario": 1, "method": "summarization", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["flannel shirt", "foam block"], "completion": "", "placements": [["flannel shirt", "hamper"], ["foam block", "toy chest"]]})" "\n"
        << R"({"scenario": 1, "method": "summarization", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["polo shirt", "wooden block"], "completion": "", "placements": [["polo shirt", "hamper"], ["wooden block", "hamper"]]})" "\n"
        << R"({"scenario": 1, "method": "commonsense", "step": "placement", "receptacles": ["hamper", "toy chest"], "objects": ["flannel shirt", "foam block"], "completion": "", "placements": [["flannel shirt", "toy chest"]]})" "\n";
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::filesystem::path path_;
};

TEST_F(PlacementCorpus, AnswersBySameContent) {
  ASSERT_TRUE(PlacementCorpusClient::recognizes(path_));
  auto client = PlacementCorpusClient::open(path_);
  ASSERT_TRUE(client) << client.error().describe();
  EXPECT_EQ((*client)->size(), 4u);
  const PreferencePrompts prompts = shipped_prompts();
  // The examples in another order, and in other words for the same names.
  auto summary = (*client)->complete(prompts.summary_request({"toy chest", "hamper"}, {{"wooden block", "toy chest"}, {"Polo Shirt", "hamper"}}));
  ASSERT_TRUE(summary);
  EXPECT_TRUE(summary->answered);
  EXPECT_EQ(summary->text, "Put shirts in the hamper and blocks in the toy chest.");
  EXPECT_EQ(summary->source, ResponseSource::kCorpus);
  // Things from two recorded answers, each from the one that placed it.
  auto placed = (*client)->complete(prompts.placement_request(
      {"hamper", "toy chest"}, "put shirts in the hamper and blocks in the toy chest", {}, {"foam block", "polo shirt", "teapot"}));
  ASSERT_TRUE(placed);
  EXPECT_EQ(placed->text, "foam block -> toy chest\npolo shirt -> hamper");
  auto common = (*client)->complete(prompts.placement_request({"hamper", "toy chest"}, "", {}, {"flannel shirt", "foam block"}));
  ASSERT_TRUE(common);
  EXPECT_EQ(common->text, "flannel shirt -> toy chest") << "the commonsense answer left the foam block out";
}

TEST_F(PlacementCorpus, WhatNoRecordMatchesIsAnsweredNothing) {
  auto client = PlacementCorpusClient::open(path_);
  ASSERT_TRUE(client);
  const PreferencePrompts prompts = shipped_prompts();
  for (const CompletionRequest& request :
       {prompts.summary_request({"hamper"}, {{"polo shirt", "hamper"}}),
        prompts.placement_request({"hamper", "toy chest"}, "Put everything in the hamper.", {}, {"foam block"}),
        prompts.placement_request({"hamper", "toy chest"}, "", {{"polo shirt", "hamper"}}, {"foam block"})}) {
    auto answer = (*client)->complete(request);
    ASSERT_TRUE(answer);
    EXPECT_FALSE(answer->answered) << request.prompt;
  }
  CompletionRequest goal;
  goal.prompt = "a goal";
  goal.about.object_category = "foam-block";
  auto answer = (*client)->complete(goal);
  ASSERT_TRUE(answer);
  EXPECT_FALSE(answer->answered);
}

TEST_F(PlacementCorpus, CorpusSpecChoosesItByItsKeysAndRefusesConditions) {
  auto client = make_llm_client("corpus:" + path_.string(), LlmOptions{});
  ASSERT_TRUE(client) << client.error().describe();
  EXPECT_THAT((*client)->describe(), HasSubstr("recorded summaries and placements"));
  auto pooled = make_llm_client("corpus:" + path_.string() + ",pool=all", LlmOptions{});
  ASSERT_FALSE(pooled);
  EXPECT_THAT(pooled.error().message, HasSubstr("no conditions to choose"));
  std::ofstream(path_, std::ios::app) << "{\"method\": \"summarization\", \"step\": \"guess\", \"receptacles\": []}\n";
  auto broken = PlacementCorpusClient::open(path_);
  ASSERT_FALSE(broken);
  EXPECT_EQ(broken.error().code, ErrorCode::kDataLoss);
  EXPECT_THAT(broken.error().message, HasSubstr(":5: not a placement corpus line"));
}

TEST_F(PlacementCorpus, ACassetteKeepsAPreferenceQueryAndReplaysItByMeaning) {
  const auto cassette = path_.string() + ".cassette";
  auto inner = PlacementCorpusClient::open(path_);
  ASSERT_TRUE(inner);
  const PreferencePrompts prompts = shipped_prompts();
  const CompletionRequest request =
      prompts.summary_request({"hamper", "toy chest"}, {{"polo shirt", "hamper"}, {"wooden block", "toy chest"}});
  {
    auto recording = RecordingClient::open(cassette, std::move(*inner));
    ASSERT_TRUE(recording);
    ASSERT_TRUE((*recording)->complete(request));
  }
  auto replay = ReplayClient::open(cassette);
  ASSERT_TRUE(replay) << replay.error().describe();
  CompletionRequest reworded = request;
  reworded.prompt = "another prompt, the same meaning";
  auto answer = (*replay)->complete(reworded);
  ASSERT_TRUE(answer) << answer.error().describe();
  EXPECT_EQ(answer->text, "Put shirts in the hamper and blocks in the toy chest.");
  CompletionRequest other = reworded;
  other.about.examples.pop_back();
  EXPECT_FALSE((*replay)->complete(other)) << "other examples are another query";
  std::filesystem::remove(cassette);
}

// The development half's recorded answers: the summary of scenario 2's
// seen placements, asked in the world's words.
TEST(TidyBotCorpus, AnswersTheDevelopmentHalfsSummaryByContent) {
  const auto path = apprentice::testing::shared_path("data/tidybot-benchmark/llm-dev.jsonl");
  APPRENTICE_REQUIRE_SHARED(path);
  auto client = PlacementCorpusClient::open(path);
  ASSERT_TRUE(client) << client.error().describe();
  EXPECT_EQ((*client)->size(), 384u);
  auto summary = (*client)->complete(shipped_prompts().summary_request(
      {"basket", "drawer"}, {{"dress", "basket"}, {"play doh", "drawer"}, {"pants", "basket"}, {"toy block", "drawer"}}));
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->text, "Put clothes in the basket and toys in the drawer.");
}

}  // namespace
}  // namespace apprentice::llm
