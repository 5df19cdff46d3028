#include "llm/corpus_client.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "llm/factory.h"
#include "llm/retrieval.h"

#include "common/paths.h"
#include "common/scratch.h"

namespace apprentice::llm {
namespace {

const std::string kFixture = std::string(APPRENTICE_SOURCE_DIR) + "/tests/llm/data/goal_corpus.jsonl";
const std::string kStars =
    std::string(APPRENTICE_SHARED_DIR) + "/data/stars-tidy-kitchen/goal_responses.jsonl";

std::unique_ptr<CorpusClient> open_corpus(const std::string& path, CorpusSelection selection = {}) {
  auto client = CorpusClient::open(path, selection);
  EXPECT_TRUE(client.has_value()) << client.error().describe();
  return client ? std::move(*client) : nullptr;
}

CompletionRequest goal_query(const std::string& object, const std::string& subtask,
                             const std::string& place, double temperature) {
  CompletionRequest request;
  request.prompt = "... (RESULT)";
  request.temperature = temperature;
  request.stop = {"(END RESULT)"};
  request.about.kind = QueryKind::kGoal;
  request.about.object_category = object;
  request.about.subtask = subtask;
  request.about.place = place;
  return request;
}

const CorpusSelection kEnsemble{"", true};

TEST(CorpusClientTest, PoolsConditionsMostOftenRetrievedFirst) {
  auto corpus = open_corpus(kFixture, kEnsemble);
  ASSERT_NE(corpus, nullptr);
  auto answers = corpus->ranked("mug", "store", "counter");
  ASSERT_EQ(answers.size(), 3u);
  // "dishwasher" 3 times (one differs only in case and spacing), "cupboard" 2, "sink" 1.
  EXPECT_EQ(answers[0].text, "the goal is that the mug is in the dishwasher and the dishwasher is closed");
  EXPECT_EQ(answers[0].count, 3);
  EXPECT_EQ(answers[1].text, "the goal is that the mug is in the cupboard");
  EXPECT_EQ(answers[2].text, "the goal is that the mug is in the sink");
  // The place keeps the dish-rack mug apart.
  EXPECT_EQ(corpus->ranked("mug", "unload", "dish rack").size(), 1u);
  EXPECT_EQ(corpus->ranked("mug", "", "").size(), 4u);
}

TEST(CorpusClientTest, OneConditionKeepsItsRankOrder) {
  auto corpus = open_corpus(kFixture, {"TBP"});
  ASSERT_NE(corpus, nullptr);
  auto answers = corpus->ranked("mug", "store", "counter");
  ASSERT_EQ(answers.size(), 3u);
  EXPECT_EQ(answers[0].text, "the goal is that the mug is in the sink");
  EXPECT_EQ(answers[2].text, "the goal is that the mug is in the cupboard");
  auto unknown = CorpusClient::open(kFixture, {"XYZ"});
  ASSERT_FALSE(unknown.has_value());
  EXPECT_EQ(unknown.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(unknown.error().message.find("it has ST, TBP"), std::string::npos) << unknown.error().message;
}

// Issue 13, item 3: a condition's responses come in that run's own order
// (the rank field), not in the order of the lines nor by how often they
// recur; and they carry no invented probability.
TEST(CorpusClientTest, AConditionIsInItsRankOrderWithoutProbabilities) {
  ::apprentice::testing::ScratchDir scratch;
  const auto path = scratch / "rank_corpus.jsonl";
  std::ofstream(path) << R"({"condition":"A","object":"mug","rank":2,"response":"the goal is that the mug is in the sink"}
{"condition":"A","object":"mug","rank":0,"response":"the goal is that the mug is in the cupboard"}
{"condition":"A","object":"mug","rank":1,"response":"the goal is that the mug is in the sink"}
{"condition":"A","object":"mug","rank":3,"response":"The goal is that the mug is in  the drawer"}
{"condition":"B","object":"mug","rank":0,"response":"the goal is that the mug is in the drawer"}
{"condition":"B","object":"mug","rank":1,"response":"the goal is that the mug is in the drawer"}
)";
  auto a = open_corpus(path.string(), {"A"});
  auto ensemble = open_corpus(path.string(), kEnsemble);
  auto several = CorpusClient::open(path, {});  // no TBP, two conditions: must choose
  ASSERT_NE(a, nullptr);
  auto answers = a->ranked("mug", "", "");
  ASSERT_EQ(answers.size(), 3u);
  EXPECT_EQ(answers[0].text, "the goal is that the mug is in the cupboard");
  EXPECT_EQ(answers[1].text, "the goal is that the mug is in the sink");  // at its best rank, 1
  EXPECT_EQ(answers[2].text, "The goal is that the mug is in  the drawer");
  auto top = a->complete(goal_query("mug", "", "", 0.0));
  ASSERT_TRUE(top.has_value());
  EXPECT_FALSE(mean_logprob(top->tokens).has_value());
  EXPECT_EQ(a->describe().find("ensemble"), std::string::npos);
  EXPECT_FALSE(a->pools_sources());
  // Pooled, the drawer (3 of 6 lines) comes first, with its share.
  ASSERT_NE(ensemble, nullptr);
  EXPECT_TRUE(ensemble->pools_sources());
  EXPECT_NE(ensemble->describe().find("ensemble"), std::string::npos);
  auto pooled = ensemble->complete(goal_query("mug", "", "", 0.0));
  ASSERT_TRUE(pooled.has_value());
  EXPECT_NE(pooled->text.find("drawer"), std::string::npos);
  EXPECT_NEAR(std::exp(*mean_logprob(pooled->tokens)), 0.5, 1e-12);
  ASSERT_FALSE(several.has_value());
  EXPECT_EQ(several.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(several.error().message.find("pool=all"), std::string::npos) << several.error().message;
}

TEST(CorpusClientTest, TheDefaultIsTbpAndTheSpecChoosesOtherwise) {
  auto by_default = make_llm_client("corpus:" + kFixture, LlmOptions{});
  ASSERT_TRUE(by_default.has_value()) << by_default.error().describe();
  EXPECT_NE((*by_default)->describe().find("(condition TBP)"), std::string::npos);
  auto pooled = make_llm_client("corpus:" + kFixture + ",pool=all", LlmOptions{});
  ASSERT_TRUE(pooled.has_value()) << pooled.error().describe();
  EXPECT_TRUE((*pooled)->pools_sources());
  auto st = make_llm_client("corpus:" + kFixture + ",condition=ST", LlmOptions{});
  ASSERT_TRUE(st.has_value()) << st.error().describe();
  EXPECT_NE((*st)->describe().find("(condition ST)"), std::string::npos);
  EXPECT_EQ(make_llm_client("corpus:" + kFixture + ",pool=some", LlmOptions{}).error().code, ErrorCode::kInvalidInput);
  EXPECT_EQ(make_llm_client("corpus:" + kFixture + ",condition=ST,pool=all", LlmOptions{}).error().code,
            ErrorCode::kInvalidInput);
}

// Issue 13, item 2: a re-prompt that lists rejected answers has nothing
// recorded for it: a miss, so the agent goes on as before.
TEST(CorpusClientTest, ARepromptWithRejectedAnswersIsAMiss) {
  auto corpus = open_corpus(kFixture, kEnsemble);
  ASSERT_NE(corpus, nullptr);
  CompletionRequest again = goal_query("mug", "store", "counter", 0.0);
  again.about.rejected = {"the goal is that the mug is in the sink"};
  auto nothing = corpus->complete(again);
  ASSERT_TRUE(nothing.has_value());
  EXPECT_FALSE(nothing->answered);
}

TEST(CorpusClientTest, WalksDownTheListAsTemperatureRises) {
  auto corpus = open_corpus(kFixture, kEnsemble);
  ASSERT_NE(corpus, nullptr);
  std::vector<std::string> texts;
  for (double temperature : {0.0, 0.9, 0.9, 1.0, 0.0}) {
    auto answer = corpus->complete(goal_query("Mug", "store", "on the counter", temperature));
    ASSERT_TRUE(answer.has_value());
    EXPECT_EQ(answer->source, ResponseSource::kCorpus);
    texts.push_back(answer->text);
  }
  EXPECT_EQ(texts[0], texts[4]);  // temperature 0: always the top one
  EXPECT_NE(texts[1], texts[0]);
  EXPECT_NE(texts[2], texts[1]);
  EXPECT_EQ(texts[3], texts[0]);  // wrapped round
  auto top = corpus->complete(goal_query("mug", "store", "counter", 0.0));
  // exp(mean log-probability) is the share of retrievals: 3 of 6.
  EXPECT_NEAR(std::exp(*mean_logprob(top->tokens)), 0.5, 1e-12);
  EXPECT_EQ(top->completion_tokens, 15);
}

TEST(CorpusClientTest, AnswersNothingOutsideTheCorpus) {
  auto corpus = open_corpus(kFixture, kEnsemble);
  ASSERT_NE(corpus, nullptr);
  auto missing = corpus->complete(goal_query("teapot", "clear", "table", 0.0));
  ASSERT_TRUE(missing.has_value());
  EXPECT_FALSE(missing->answered);
  CompletionRequest action = goal_query("mug", "store", "counter", 0.0);
  action.about.kind = QueryKind::kActionWord;
  auto nothing = corpus->complete(action);
  ASSERT_TRUE(nothing.has_value());
  EXPECT_FALSE(nothing->answered);
  EXPECT_EQ(corpus->usage().unanswered, 2);
  EXPECT_NE(corpus->describe().find("ensemble: all conditions pooled"), std::string::npos);
}

TEST(CorpusClientTest, ServesRetrieveGoals) {
  auto corpus = make_llm_client("corpus:" + kFixture + ",pool=all", LlmOptions{});
  ASSERT_TRUE(corpus.has_value()) << corpus.error().describe();
  auto templates = PromptTemplates::load(apprentice::testing::source_path("data/prompts"));
  ASSERT_TRUE(templates.has_value());
  TaskContext context{"tidy kitchen", "store", "kitchen", "mug", "on counter"};
  Retrieval goals = retrieve_goals(**corpus, *templates, context);
  ASSERT_EQ(goals.candidates.size(), 3u);
  EXPECT_EQ(goals.queries, 3);
  EXPECT_EQ(goals.candidates[0].source, ResponseSource::kCorpus);
  EXPECT_EQ(goals.candidates[0].text,
            "the goal is that the mug is in the dishwasher and the dishwasher is closed");
  TaskContext elsewhere = context;
  elsewhere.object = "teapot";
  Retrieval none = retrieve_goals(**corpus, *templates, elsewhere);
  EXPECT_TRUE(none.candidates.empty());
  EXPECT_TRUE(none.unanswered);
  EXPECT_EQ(none.queries, 1);  // no point asking again
}

TEST(CorpusClientTest, ConditionInTheSpec) {
  auto corpus = make_llm_client("corpus:" + kFixture + ",condition=TBP", LlmOptions{});
  ASSERT_TRUE(corpus.has_value()) << corpus.error().describe();
  EXPECT_NE((*corpus)->describe().find("condition TBP"), std::string::npos);
}

TEST(CorpusClientTest, BadLinesNameTheLine) {
  const auto path = std::filesystem::temp_directory_path() / "apprentice_bad_corpus.jsonl";
  std::ofstream(path) << "{\"object\": \"mug\", \"response\": \"x\"}\n{\"object\": 1}\n";
  auto corpus = CorpusClient::open(path);
  std::filesystem::remove(path);
  ASSERT_FALSE(corpus.has_value());
  EXPECT_EQ(corpus.error().code, ErrorCode::kDataLoss);
  EXPECT_NE(corpus.error().message.find(":2:"), std::string::npos) << corpus.error().message;
}

TEST(CorpusClientTest, NumbersOutOfRangeAreBadLinesNotExceptions) {
  ::apprentice::testing::ScratchDir scratch;
  const auto path = scratch / "corpus_1e400.jsonl";
  std::ofstream(path) << "{\"object\": \"mug\", \"response\": \"x\", \"rank\": 1e400}\n";
  auto corpus = CorpusClient::open(path);
  ASSERT_FALSE(corpus.has_value());
  EXPECT_EQ(corpus.error().code, ErrorCode::kDataLoss);
  EXPECT_NE(corpus.error().message.find(":1:"), std::string::npos) << corpus.error().message;
}

TEST(CorpusClientTest, RealStarsCorpus) {
  APPRENTICE_REQUIRE_SHARED(kStars);
  auto pooled = open_corpus(kStars, kEnsemble);
  ASSERT_NE(pooled, nullptr);
  auto plate = pooled->ranked("ceramic-plate", "clear", "table");
  ASSERT_GE(plate.size(), 3u);
  EXPECT_GE(plate[0].count, plate[1].count);
  EXPECT_GE(plate[1].count, plate[2].count);
  // The plate in the dish rack is another query with other answers.
  auto rack = pooled->ranked("ceramic-plate", "unload", "dish rack");
  ASSERT_FALSE(rack.empty());
  EXPECT_NE(rack[0].text.find("cupboard"), std::string::npos);  // unloading: put away

  auto tbp = open_corpus(kStars);  // TBP by default
  ASSERT_NE(tbp, nullptr);
  auto bottle = tbp->ranked("plastic-bottle", "clear", "table");
  ASSERT_EQ(bottle.size(), 3u);  // TBP retrieved three unique responses per object
  EXPECT_EQ(bottle[0].text,
            "the goal is that the plastic-bottle is in the recycle-bin and the recycle-bin is closed");
  auto templates = PromptTemplates::load(apprentice::testing::source_path("data/prompts"));
  ASSERT_TRUE(templates.has_value());
  TaskContext context{"tidy kitchen", "clear", "kitchen", "plastic-bottle", "on table"};
  Retrieval goals = retrieve_goals(*tbp, *templates, context);
  ASSERT_EQ(goals.candidates.size(), 3u);
  EXPECT_EQ(goals.candidates[0].text, bottle[0].text);
  EXPECT_EQ(goals.candidates[1].text, bottle[1].text);
  EXPECT_EQ(tbp->condition(), "TBP");
}

}  // namespace
}  // namespace apprentice::llm
