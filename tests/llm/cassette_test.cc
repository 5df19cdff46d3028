#include "common/paths.h"
#include "llm/cassette.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "llm/factory.h"
#include "llm/fake_llm.h"
#include "llm/retrieval.h"
#include "llm/test_server.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;
using testing::FakeClient;

class CassetteTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("apprentice_cassette_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string read(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }
  std::filesystem::path dir_;
};

// An OpenAI-format body for `text`, one token per word.
std::string openai_body(const std::string& text, double logprob,
                        const std::vector<std::pair<std::string, double>>& top = {}) {
  json tokens = json::array(), logprobs = json::array(), tops = json::array();
  for (const std::string& word : split_words(text)) {
    tokens.push_back(" " + word);
    logprobs.push_back(logprob);
    json alternatives = json::object();
    alternatives[" " + word] = logprob;
    tops.push_back(alternatives);
  }
  if (!top.empty()) {
    json alternatives = json::object();
    for (const auto& [token, lp] : top) alternatives[token] = lp;
    tops = json::array({alternatives});
  }
  json body = {{"object", "text_completion"},
               {"choices", json::array({json{{"text", " " + text},
                                             {"index", 0},
                                             {"finish_reason", "stop"},
                                             {"logprobs", json{{"tokens", tokens},
                                                               {"token_logprobs", logprobs},
                                                               {"top_logprobs", tops}}}}})},
               {"usage", json{{"prompt_tokens", 300}, {"completion_tokens", tokens.size()}}}};
  return body.dump();
}

// A model that gives varied answers, as a real one at temperature > 0 does.
void serve_model(testing::TestHttpServer& server, std::atomic<int>& calls) {
  server.server().Post("/v1/completions", [&calls](const httplib::Request& req, httplib::Response& res) {
    const int call = calls++;
    json request = json::parse(req.body);
    const std::string prompt = request["prompt"];
    std::string body;
    if (request["max_tokens"] == 1) {
      body = openai_body("Open", -0.6,
                         {{" Open", -0.6}, {" Pick", -1.58}, {" Check", -2.7}, {" Go", -2.73}, {" If", -3.6}});
    } else if (prompt.ends_with("(RESULT)")) {
      static const char* const kGoals[] = {
          "The goal is that the ceramic-plate is in the cupboard and the cupboard is closed",
          "The goal is that the ceramic-plate is in the dishwasher and the dishwasher is turned on",
          "The goal is that the ceramic-plate is in the café sink"};
      const int pick = request["temperature"] == 0.0 ? 0 : call % 3;
      body = openai_body(kGoals[pick], -0.05 * (pick + 1));
    } else if (prompt.ends_with(" Open")) {
      body = openai_body("dishwasher", -0.001);
    } else {
      body = openai_body(call % 2 ? "up ceramic-plate from table." : "up ceramic-plate", -0.05);
    }
    res.set_content(body, "application/json");
  });
  server.start();
}

// The agent's LLM part of one object: goals, then the first step.
std::pair<Retrieval, Retrieval> run_once(LlmClient& client) {
  auto templates = PromptTemplates::load(apprentice::testing::source_path("data/prompts"));
  EXPECT_TRUE(templates.has_value());
  TaskContext plate{"tidy kitchen", "clear", "kitchen", "ceramic-plate", "on table"};
  Retrieval goals = retrieve_goals(client, *templates, plate);
  Retrieval actions = retrieve_actions(
      client, *templates, plate,
      "If the object is a ceramic-plate then the goal is that the object is in the dishwasher",
      {}, [](std::string_view word) { return word == "Open" || word == "Pick"; });
  return {goals, actions};
}

TEST_F(CassetteTest, ReplayReproducesARecordedRunToTheByte) {
  testing::TestHttpServer server;
  std::atomic<int> calls{0};
  serve_model(server, calls);
  LlmOptions options;
  options.api_key = "sk-never-in-a-cassette";
  auto recorder = make_llm_client("record:" + path("run.jsonl") + ",openai:" + server.url() + "/v1", options);
  ASSERT_TRUE(recorder.has_value()) << recorder.error().describe();
  auto [goals, actions] = run_once(**recorder);
  ASSERT_FALSE(goals.failure.has_value()) << goals.failure->describe();
  EXPECT_EQ(goals.candidates.size(), 3u);
  EXPECT_EQ(actions.candidates.size(), 3u);  // Open dishwasher, Pick up ..., Pick up ... table.
  recorder->reset();

  const int live_calls = calls.load();
  auto rerun = make_llm_client("record:" + path("rerun.jsonl") + ",replay:" + path("run.jsonl"), options);
  ASSERT_TRUE(rerun.has_value()) << rerun.error().describe();
  auto [goals2, actions2] = run_once(**rerun);
  rerun->reset();
  EXPECT_EQ(calls.load(), live_calls);  // offline: the server saw nothing more
  EXPECT_EQ(goals2.candidates, goals.candidates);
  EXPECT_EQ(actions2.candidates, actions.candidates);
  EXPECT_EQ(goals2.queries, goals.queries);
  const std::string recorded = read(path("run.jsonl"));
  EXPECT_FALSE(recorded.empty());
  EXPECT_EQ(read(path("rerun.jsonl")), recorded);
  EXPECT_EQ(recorded.find("sk-never-in-a-cassette"), std::string::npos);
  EXPECT_NE(recorded.find("caf\xC3\xA9"), std::string::npos);  // UTF-8 kept as is
}

TEST_F(CassetteTest, ErrorsAreRecordedAndReplayed) {
  auto recorder = RecordingClient::open(path("errors.jsonl"), std::make_unique<FakeClient>(
      [](const CompletionRequest&, size_t call) -> Result<Completion> {
        if (call == 0) return make_error(ErrorCode::kDeadlineExceeded, "no answer in time");
        return testing::answer("the goal is that the mug is in the sink");
      }));
  ASSERT_TRUE(recorder.has_value());
  CompletionRequest request;
  request.prompt = "p";
  EXPECT_FALSE((*recorder)->complete(request).has_value());
  EXPECT_TRUE((*recorder)->complete(request).has_value());
  recorder->reset();
  auto replay = ReplayClient::open(path("errors.jsonl"));
  ASSERT_TRUE(replay.has_value()) << replay.error().describe();
  auto first = (*replay)->complete(request);
  ASSERT_FALSE(first.has_value());
  EXPECT_EQ(first.error().code, ErrorCode::kDeadlineExceeded);
  EXPECT_EQ(first.error().message, "no answer in time");
  auto second = (*replay)->complete(request);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->text, " the goal is that the mug is in the sink");
  // Used up: given again from the first.
  EXPECT_FALSE((*replay)->complete(request).has_value());
}

TEST_F(CassetteTest, FindsAnswersByMeaningWhenThePromptDiffers) {
  QueryAbout about;
  about.kind = QueryKind::kGoal;
  about.task = "tidy kitchen";
  about.subtask = "clear";
  about.object_category = "ceramic-plate";
  about.place = "table";
  {
    auto recorder = RecordingClient::open(path("m.jsonl"), std::make_unique<FakeClient>(
        [](const CompletionRequest&, size_t) -> Result<Completion> {
          return testing::answer("the goal is that the ceramic-plate is in the cupboard");
        }));
    ASSERT_TRUE(recorder.has_value());
    CompletionRequest request;
    request.prompt = "old template wording (RESULT)";
    request.about = about;
    ASSERT_TRUE((*recorder)->complete(request).has_value());
  }
  auto replay = ReplayClient::open(path("m.jsonl"));
  ASSERT_TRUE(replay.has_value());
  CompletionRequest request;
  request.prompt = "new template wording (RESULT)";
  request.temperature = 0.9;
  request.about = about;
  request.about.object_category = "Ceramic Plate";  // same meaning
  request.about.place = "on the table";
  auto answer = (*replay)->complete(request);
  ASSERT_TRUE(answer.has_value()) << answer.error().describe();
  EXPECT_EQ(answer->text, " the goal is that the ceramic-plate is in the cupboard");

  // A re-prompt listing a rejected answer was not recorded: a quiet miss
  // (answered = false), as a corpus gives, not an error.
  request.about.object_category = "ceramic-plate";
  request.about.rejected = {"the goal is that the ceramic-plate is in the cupboard"};
  auto reprompt = (*replay)->complete(request);
  ASSERT_TRUE(reprompt.has_value()) << reprompt.error().describe();
  EXPECT_FALSE(reprompt->answered);

  request.about.rejected.clear();
  request.about.object_category = "mug";
  auto missing = (*replay)->complete(request);
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
  EXPECT_NE(missing.error().message.find("nothing recorded"), std::string::npos);
}

TEST_F(CassetteTest, CorruptCassetteNamesTheLine) {
  std::ofstream(path("bad.jsonl")) << "\n{\"request\": 3}\n";
  auto replay = ReplayClient::open(path("bad.jsonl"));
  ASSERT_FALSE(replay.has_value());
  EXPECT_EQ(replay.error().code, ErrorCode::kDataLoss);
  EXPECT_NE(replay.error().message.find("bad.jsonl:2"), std::string::npos) << replay.error().message;
  EXPECT_EQ(ReplayClient::open(path("absent.jsonl")).error().code, ErrorCode::kNotFound);
}

// Issue 11, defect 1: numbers out of range in a cassette line are a clear
// kDataLoss, never an exception or a cast out of range.
TEST(ExchangeLineTest, NumbersOutOfRangeAreUnreadableLines) {
  Exchange exchange;
  exchange.request.prompt = "p";
  exchange.response = testing::answer("x", -0.5);
  const std::string good = exchange_to_line(exchange);
  ASSERT_TRUE(exchange_from_line(good).has_value());
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string line = good;
    const size_t at = line.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? line : line.replace(at, from.size(), to);
  };
  for (const std::string& line :
       {replace("\"temperature\":0.0", "\"temperature\":1e400"), replace("\"max_tokens\":64", "\"max_tokens\":1e300"),
        replace("\"top_logprobs\":1}", "\"top_logprobs\":-3}"), replace("\"prompt_tokens\":0", "\"prompt_tokens\":1e30"),
        replace("-0.5", "1e999")}) {
    SCOPED_TRACE(line);
    auto back = exchange_from_line(line);
    ASSERT_FALSE(back.has_value());
    EXPECT_EQ(back.error().code, ErrorCode::kDataLoss);
  }
}

TEST(ExchangeLineTest, RoundTripsEveryField) {
  Exchange exchange;
  exchange.request.prompt = "Steps:\n1.";
  exchange.request.temperature = 0.9;
  exchange.request.max_tokens = 24;
  exchange.request.stop = {"\n"};
  exchange.request.top_logprobs = 5;
  exchange.request.about = QueryAbout{QueryKind::kAction, "tidy kitchen", "clear", "mug", "counter",
                                      "the goal is that ...", {"Open dishwasher"}, "Pick",
                                      {"the goal is that the mug is in the sink"}};
  Completion completion = testing::answer("up mug", -0.123456789012345);
  completion.tokens.push_back(TokenLogprob{"\xE2\x82\xAC", std::numeric_limits<double>::quiet_NaN()});
  completion.prompt_tokens = 301;
  completion.raw = "{\"x\":1}";
  exchange.response = completion;
  const std::string line = exchange_to_line(exchange);
  auto back = exchange_from_line(line);
  ASSERT_TRUE(back.has_value()) << back.error().describe();
  EXPECT_EQ(back->request, exchange.request);
  ASSERT_TRUE(back->response.has_value());
  EXPECT_EQ(*back->response, completion);
  EXPECT_EQ(exchange_to_line(*back), line);
}

}  // namespace
}  // namespace apprentice::llm
