// A failing LLM never spoils a learning run. Against a local server that
// fails in each way a real one does, a run of an LLM condition completes
// the task with the instructor taking over: the agent says it could not
// reach the model, asks instead, keeps everything it learns, and after 3
// failed queries in a row does not ask the model again (the circuit
// breaker), so the time lost is bounded by the number of requests, which
// the tests count; no test here holds a tight wall-clock bound.
#include <chrono>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "experiment_fixtures.h"
#include "fake_llm_server.h"
#include "knowledge/store.h"
#include <nlohmann/json.hpp>

namespace apprentice {
namespace {

using testing::experiment_options;
using testing::factory;
using testing::FakeLlmServer;
using testing::load_or_die;
using testing::ServerMode;
using testing::source_path;
using ::testing::HasSubstr;

constexpr const char* kCouldNotReach = "Agent: I could not reach the language model (";

// The run without any LLM, which a run whose LLM always fails must equal
// in everything the instructor says.
const ConditionResult& baseline(const Scenario& scenario, const std::string& condition) {
  static std::map<std::string, ConditionResult> cache;
  std::string key = scenario.name + "/" + condition;
  auto found = cache.find(key);
  if (found == cache.end()) found = cache.emplace(key, testing::run(scenario, condition, experiment_options())).first;
  return found->second;
}

// What the instructor said, in order.
std::vector<std::string> instructor_lines(const std::string& transcript) {
  std::vector<std::string> out;
  std::istringstream in(transcript);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("Instructor: ", 0) == 0) out.push_back(line);
  return out;
}

struct FaultCase {
  const char* name;
  ServerMode mode;
  const char* scenario;   // relative to the source directory
  const char* condition;  // an LLM condition
  const char* without_llm;
  int attempts_per_query;  // 1 + retries for a failure that is retried, else 1
};

// The breaker's threshold (LlmAdvisorOptions::breaker_threshold).
constexpr int kBreaker = 3;
// Only a loose guard against a hang: the bound that matters is on requests.
constexpr double kHangGuardSeconds = 120.0;

void PrintTo(const FaultCase& c, std::ostream* out) { *out << c.name; }

class LlmFault : public testing::ScratchTest, public ::testing::WithParamInterface<FaultCase> {};

void expect_instructor_takes_over(const Scenario& scenario, const FaultCase& c, const ConditionResult& result,
                                  double seconds, const std::filesystem::path& knowledge_dir) {
  const ConditionResult& without = baseline(scenario, c.without_llm);
  EXPECT_EQ(result.completion_rate, 100.0);
  EXPECT_EQ(result.assertions_achieved, result.assertions_total);
  // The instructor said exactly what it says when there is no LLM at all.
  EXPECT_EQ(result.counts.instructions, without.counts.instructions);
  EXPECT_EQ(result.counts.words, without.counts.words);
  EXPECT_EQ(result.counts.yes_no, 0);
  EXPECT_EQ(instructor_lines(result.transcript), instructor_lines(without.transcript));
  // The agent tried, said it could not reach the model, and asked.
  EXPECT_GT(result.llm_calls, 0);
  EXPECT_THAT(result.transcript, HasSubstr(kCouldNotReach));
  EXPECT_THAT(result.transcript, HasSubstr("), so I will ask.\n"));
  EXPECT_EQ(result.relevance, std::nullopt);  // no yes/no question was asked
  // The breaker: 3 failed queries, then the model is not asked again; the
  // row is degraded.
  EXPECT_EQ(result.llm_failures, kBreaker);
  EXPECT_EQ(result.llm_calls, kBreaker);
  EXPECT_TRUE(result.llm_stopped);
  EXPECT_TRUE(result.degraded());
  // The agent said so once per failed query, and then not again.
  int said = 0;
  for (size_t at = result.transcript.find(kCouldNotReach); at != std::string::npos;
       at = result.transcript.find(kCouldNotReach, at + 1))
    ++said;
  EXPECT_EQ(said, kBreaker);
  // Nothing learned was lost: every goal is in the store.
  EXPECT_EQ(result.agent.goals_learned, without.agent.goals_learned);
  auto store = KnowledgeStore::open(knowledge_dir / (std::string(c.condition) + ".sqlite"));
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  auto knowledge = store->load(*scenario.world.domain);
  ASSERT_TRUE(knowledge.has_value()) << knowledge.error().describe();
  EXPECT_EQ(static_cast<int>(knowledge->goals.size()), without.agent.goals_learned);
  EXPECT_EQ(knowledge->tasks.size(), 1u);
  EXPECT_LT(seconds, kHangGuardSeconds);
  std::printf("%s: %s %d LLM calls, %.1f s\n", c.name, c.condition, result.llm_calls, seconds);
}

TEST_P(LlmFault, TheInstructorTakesOverAndNothingIsLost) {
  const FaultCase& c = GetParam();
  Scenario scenario = load_or_die(source_path(c.scenario));
  FakeLlmServer server(c.mode);
  ExperimentOptions options = experiment_options(factory("openai:" + server.url()));
  options.knowledge_out = dir_;
  auto started = std::chrono::steady_clock::now();
  ConditionResult result = testing::run(scenario, c.condition, options);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(server.requests(), kBreaker * c.attempts_per_query);
  expect_instructor_takes_over(scenario, c, result, seconds, dir_);
}

// Fast failures on the paper's kitchen; slow ones on a small kitchen,
// since every query then costs the whole (300 ms) timeout.
INSTANTIATE_TEST_SUITE_P(
    Servers, LlmFault,
    ::testing::Values(
        FaultCase{"500s_inst_llm", ServerMode::kStatus500, "data/scenarios/tidy-kitchen.yaml", "inst+llm", "instruction",
                  2},
        FaultCase{"500s_inst_search4_llm", ServerMode::kStatus500, "data/scenarios/tidy-kitchen.yaml",
                  "inst+search4+llm", "inst+search4", 2},
        FaultCase{"429_retry_after_inst_llm", ServerMode::kRateLimited, "data/scenarios/tidy-kitchen.yaml", "inst+llm",
                  "instruction", 2},
        FaultCase{"malformed_json_inst_llm", ServerMode::kMalformedJson, "data/scenarios/tidy-kitchen.yaml",
                  "inst+llm", "instruction", 1},
        FaultCase{"not_a_completion_inst_search2_llm", ServerMode::kWrongJson, "data/scenarios/tidy-kitchen.yaml",
                  "inst+search2+llm", "inst+search2", 1},
        FaultCase{"timeout_inst_search4_llm", ServerMode::kSlow, "tests/experiment/data/small-kitchen.yaml",
                  "inst+search4+llm", "inst+search4", 1},
        FaultCase{"timeout_inst_llm", ServerMode::kSlow, "tests/experiment/data/small-kitchen.yaml", "inst+llm",
                  "instruction", 1}),
    [](const ::testing::TestParamInfo<FaultCase>& info) { return std::string(info.param.name); });

class LlmUnreachable : public testing::ScratchTest {};

TEST_F(LlmUnreachable, AHungConnectionTimesOutAndTheInstructorTakesOver) {
  Scenario scenario = load_or_die(source_path("tests/experiment/data/small-kitchen.yaml"));
  testing::HungServer server;
  ExperimentOptions options = experiment_options(factory("openai:" + server.url()));
  options.knowledge_out = dir_;
  auto started = std::chrono::steady_clock::now();
  ConditionResult result = testing::run(scenario, "inst+search4+llm", options);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // Each query waits out the whole timeout and is not retried: 3 of them,
  // then the breaker. So the condition costs 3 timeouts, not one per query.
  expect_instructor_takes_over(scenario,
                               FaultCase{"hung", ServerMode::kSlow, "", "inst+search4+llm", "inst+search4", 1}, result,
                               seconds, dir_);
  EXPECT_THAT(result.transcript, HasSubstr("in time"));
}

TEST_F(LlmUnreachable, ARefusedConnectionIsReportedAndTheInstructorTakesOver) {
  Scenario scenario = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  std::string url = "http://127.0.0.1:" + std::to_string(testing::closed_port()) + "/v1";
  ExperimentOptions options = experiment_options(factory("openai:" + url));
  options.knowledge_out = dir_;
  auto started = std::chrono::steady_clock::now();
  ConditionResult result = testing::run(scenario, "inst+llm", options);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  expect_instructor_takes_over(scenario, FaultCase{"refused", ServerMode::kSlow, "", "inst+llm", "instruction", 2},
                               result, seconds, dir_);
}

TEST_F(LlmUnreachable, WithoutAnInstructorTheRunEndsWithoutGoalsButCleanly) {
  // search4+llm has nobody to ask: the objects fail, the run does not.
  Scenario scenario = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  FakeLlmServer server(ServerMode::kStatus500);
  ConditionResult result =
      testing::run(scenario, "search4+llm", experiment_options(factory("openai:" + server.url())));
  EXPECT_LT(result.completion_rate, 100.0);
  EXPECT_EQ(result.counts.instructions, 14);  // the task structure alone
  EXPECT_EQ(result.counts.words, 76);
  EXPECT_THAT(result.transcript, HasSubstr(kCouldNotReach));
  EXPECT_THAT(result.transcript, ::testing::Not(HasSubstr("so I will ask")));
  EXPECT_EQ(result.agent.goals_learned, 0);
  EXPECT_EQ(result.llm_failures, kBreaker);
  EXPECT_EQ(server.requests(), kBreaker * 2);
}

TEST(LlmRateLimit, ARetryAfterA429GetsTheAnswerAndTheLlmIsUsed) {
  // Every other request is refused with 429 and Retry-After: the client
  // waits (capped at 5 ms here) and retries once, and gets the answer.
  Scenario scenario = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  FakeLlmServer server(ServerMode::kRateLimitedOnce,
                       {{"ketchup", {"The goal is that the X is in the fridge and the fridge is closed"}},
                        {"milk", {"The goal is that the X is in the fridge and the fridge is closed"}}});
  llm::LlmOptions options = testing::fast_failing_options();
  options.transport.retry_after_cap = std::chrono::milliseconds(5);
  // Not a timeout test: a busy machine must not turn a slow answer into a failure.
  options.transport.request_timeout = std::chrono::milliseconds(10'000);
  auto started = std::chrono::steady_clock::now();
  ConditionResult result =
      testing::run(scenario, "inst+search4+llm", experiment_options(factory("openai:" + server.url(), options)));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(result.completion_rate, 100.0);
  EXPECT_THAT(result.transcript, ::testing::Not(HasSubstr(kCouldNotReach)));
  // The two goals the model knows were proposed and accepted.
  EXPECT_THAT(result.transcript, HasSubstr("For a ketchup on the table, is the goal that the ketchup is in the fridge "
                                           "and the fridge is closed?\nInstructor: yes.\n"));
  EXPECT_GE(result.counts.yes, 2);
  EXPECT_EQ(server.requests(), 2 * result.llm_calls);
  EXPECT_EQ(result.llm_failures, 0);
  EXPECT_FALSE(result.degraded());
  EXPECT_LT(seconds, kHangGuardSeconds);
}

// Issue 13, item 6, as a user meets it on the command line.
class LlmCli : public testing::ScratchTest {
 protected:
  static int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }
  std::vector<std::string> experiment(const std::string& conditions, const std::string& llm) const {
    return {"experiment", "--scenario", source_path("data/scenarios/tidy-kitchen.yaml").string(), "--conditions",
            conditions, "--llm", llm};
  }
};

TEST_F(LlmCli, ADeadServerExits4AtOnceWithOneLine) {
  const std::string dead = "openai:http://127.0.0.1:" + std::to_string(testing::closed_port()) + "/v1";
  auto started = std::chrono::steady_clock::now();
  testing::Invocation run = testing::run_cli(experiment("instruction,inst+llm", dead), dir_);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(run.exit_code, 4) << run.err;
  EXPECT_EQ(lines(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("apprentice: unavailable: cannot get an answer from the LLM server at http://127.0.0.1:"));
  EXPECT_THAT(run.err, HasSubstr("(--llm-optional goes on without it)"));
  EXPECT_EQ(run.out, "");  // checked before any condition runs
  EXPECT_LT(seconds, 20.0);  // the bound; it is one refused connection
}

TEST_F(LlmCli, WithLlmOptionalADeadServerIsDoneWithout) {
  const std::string dead = "openai:http://127.0.0.1:" + std::to_string(testing::closed_port()) + "/v1";
  auto args = experiment("inst+llm", dead);
  args.push_back("--llm-optional");
  testing::Invocation run = testing::run_cli(args, dir_);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LE(lines(run.err), 5) << run.err;
  EXPECT_THAT(run.err, HasSubstr("going on without the LLM"));
  EXPECT_THAT(run.out, HasSubstr("\ninst+llm*          ours         100.0"));
  EXPECT_THAT(run.out, HasSubstr("* inst+llm: degraded, the LLM could not be reached and was not asked\n"));
}

TEST_F(LlmCli, AServerThatFailsDuringTheRunMarksTheRowAndExits4) {
  FakeLlmServer server(ServerMode::kMalformedJson);
  server.healthy_for(1);  // the check before the run is answered
  auto args = experiment("instruction,inst+llm", "openai:" + server.url());
  args.push_back("--json");
  testing::Invocation run = testing::run_cli(args, dir_);
  EXPECT_EQ(run.exit_code, 4) << run.err;
  EXPECT_LE(lines(run.err), 5) << run.err;
  EXPECT_THAT(run.err, HasSubstr("not asked again"));
  EXPECT_THAT(run.err, HasSubstr("apprentice: unavailable: the LLM failed in inst+llm"));
  auto rows = nlohmann::json::parse(run.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["llm_failures"], 0);
  EXPECT_EQ(rows[1]["llm_failures"], kBreaker);
  EXPECT_EQ(rows[1]["completion_rate"], 100.0);  // the instructor took over
  EXPECT_EQ(server.requests(), 1 + kBreaker);
}

// A hung server, before and during a run: llm_cli_test.cc.

}  // namespace
}  // namespace apprentice
