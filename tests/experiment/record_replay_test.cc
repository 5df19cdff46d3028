// A run recorded through record:FILE,SPEC is reproduced exactly by
// replay:FILE: the same counts, relevance, LLM calls and tokens,
// completion and transcript, with the server gone.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

// A plausible model: right at once for some categories, undecided between
// places for others, sure and wrong for crackers (the instructor says no),
// and odd (ungroundable) for the rest.
FakeLlmServer::Goals plausible_goals() {
  const std::string fridge = "The goal is that the X is in the fridge and the fridge is closed";
  const std::string dishwasher = "The goal is that the X is in the dishwasher and the dishwasher is closed";
  const std::string cupboard = "The goal is that the X is in the cupboard and the cupboard is closed";
  const std::string pantry = "The goal is that the X is in the pantry and the pantry is closed";
  return {
      {"ketchup", {fridge}},
      {"milk", {fridge, "The goal is that the X is in the fridge"}},
      {"half-and-half", {fridge}},
      {"ceramic-plate", {cupboard, dishwasher}},
      {"mug", {cupboard, dishwasher, "The goal is that the X is in the sink"}},
      {"cereal-box", {cupboard, pantry}},
      {"crackers", {cupboard}},
      {"paper-plate", {"The goal is that the X is in the trash", "The goal is that the X is in the garbage"}},
      {"soda-can", {"The goal is that the X is in the recycling bin and the recycling bin is closed",
                    "The goal is that the X is in the recycling bin"}},
      {"ceramic-bowl", {cupboard}},
  };
}

void expect_same_run(const ConditionResult& recorded, const ConditionResult& replayed) {
  EXPECT_EQ(replayed.condition, recorded.condition);
  EXPECT_EQ(replayed.counts, recorded.counts);
  EXPECT_EQ(replayed.relevance, recorded.relevance);
  EXPECT_EQ(replayed.llm_calls, recorded.llm_calls);
  EXPECT_EQ(replayed.llm_tokens, recorded.llm_tokens);
  EXPECT_EQ(replayed.completion_rate, recorded.completion_rate);
  EXPECT_EQ(replayed.assertions_achieved, recorded.assertions_achieved);
  EXPECT_EQ(replayed.agent.search_nodes, recorded.agent.search_nodes);
  EXPECT_EQ(replayed.transcript, recorded.transcript);
}

class RecordReplay : public testing::ScratchTest {};

// The backends that reach a server, each with the fake server speaking its
// dialect: OpenAI's completions, OpenAI's chat and llama-server's own.
struct Backend {
  const char* name;
  std::string (*spec)(const FakeLlmServer& server);
};
const Backend kBackends[] = {
    {"openai", [](const FakeLlmServer& s) { return "openai:" + s.url(); }},
    {"openai-chat", [](const FakeLlmServer& s) { return "openai-chat:" + s.url(); }},
    {"llama", [](const FakeLlmServer& s) { return "llama:" + s.root(); }},
};

class RecordReplayEveryBackend : public testing::ScratchTest, public ::testing::WithParamInterface<Backend> {};

TEST_P(RecordReplayEveryBackend, AReplayedCassetteReproducesEachConditionExactly) {
  Scenario scenario = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  const std::vector<std::string> conditions = {"inst+llm", "inst+search2+llm", "inst+search4+llm", "search4+llm"};
  std::map<std::string, ConditionResult> recorded;
  {
    FakeLlmServer server(ServerMode::kModel, plausible_goals());
    for (const std::string& condition : conditions) {
      std::string spec = "record:" + (dir_ / (condition + ".jsonl")).string() + "," + GetParam().spec(server);
      recorded[condition] = testing::run(scenario, condition, experiment_options(factory(spec)));
    }
  }  // the server is gone: a replay cannot reach it
  for (const std::string& condition : conditions) {
    SCOPED_TRACE(condition);
    const ConditionResult& r = recorded[condition];
    // The recorded runs used the model for real.
    EXPECT_GT(r.llm_calls, 0);
    EXPECT_GT(r.llm_tokens, 0);
    ASSERT_TRUE(r.relevance.has_value());
    EXPECT_THAT(r.transcript, ::testing::Not(HasSubstr("could not reach")));
    EXPECT_EQ(r.llm_failures, 0);
    if (condition != "search4+llm") {
      EXPECT_EQ(r.completion_rate, 100.0);
      EXPECT_GT(r.counts.yes_no, 0);
      EXPECT_GT(r.counts.yes, 0);
      EXPECT_LT(r.counts.yes, r.counts.yes_no);
    }
    const std::string cassette = (dir_ / (condition + ".jsonl")).string();
    ConditionResult replayed = testing::run(scenario, condition, experiment_options(factory("replay:" + cassette)));
    expect_same_run(r, replayed);
    // Recorded again from the replay: the same cassette, to the byte.
    const std::string again = (dir_ / (condition + ".again.jsonl")).string();
    ConditionResult rerecorded = testing::run(
        scenario, condition, experiment_options(factory("record:" + again + ",replay:" + cassette)));
    expect_same_run(r, rerecorded);
    EXPECT_EQ(testing::read_text(again), testing::read_text(cassette));
    std::printf("%-17s %5.1f%% relevance %5.1f%%  %3d instructions %4d words %3d yes/no %4d LLM calls %6ld tokens\n",
                condition.c_str(), r.completion_rate, r.relevance.value_or(-1), r.counts.instructions, r.counts.words,
                r.counts.yes_no, r.llm_calls, r.llm_tokens);
  }
  // With no search the model's steps were put to the instructor too (until
  // the rules learned from them could act).
  EXPECT_THAT(recorded["inst+llm"].transcript,
              HasSubstr("[LM] For the ceramic plate, should I 'Open dishwasher'?\nInstructor: yes.\n"));
  // With search to depth 4 no step was ever needed.
  EXPECT_THAT(recorded["inst+search4+llm"].transcript, ::testing::Not(HasSubstr("should I '")));
}

INSTANTIATE_TEST_SUITE_P(Backends, RecordReplayEveryBackend, ::testing::ValuesIn(kBackends),
                         [](const ::testing::TestParamInfo<Backend>& info) {
                           std::string name = info.param.name;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST_F(RecordReplay, ACorpusRunReplaysExactly) {
  SKIP_WITHOUT_CORPUS();
  Scenario scenario = load_or_die(source_path("data/scenarios/tidy-kitchen-35.yaml"));
  for (const std::string condition : {"inst+llm", "search4+llm"}) {
    SCOPED_TRACE(condition);
    const std::string cassette = (dir_ / (condition + ".jsonl")).string();
    ConditionResult recorded = testing::run(
        scenario, condition,
        experiment_options(factory("record:" + cassette + ",corpus:" + testing::corpus_path().string())));
    ConditionResult replayed = testing::run(scenario, condition, experiment_options(factory("replay:" + cassette)));
    expect_same_run(recorded, replayed);
    // Both rankings: GPT-3's own order of one condition (the default, TBP)
    // and the ensemble.
    const std::string pooled = (dir_ / (condition + ".pooled.jsonl")).string();
    ConditionResult ensemble = testing::run(
        scenario, condition,
        experiment_options(factory("record:" + pooled + ",corpus:" + testing::corpus_path().string() + ",pool=all")));
    EXPECT_TRUE(ensemble.llm_ensemble);
    expect_same_run(ensemble, testing::run(scenario, condition, experiment_options(factory("replay:" + pooled))));
  }
}

TEST_F(RecordReplay, TheCliReplaysARecordedRunToTheSameTableAndTranscript) {
  const std::string cassette = (dir_ / "run.jsonl").string();
  std::vector<std::string> args = {"experiment", "--scenario", source_path("data/scenarios/tidy-kitchen.yaml").string(),
                                   "--conditions", "inst+search2+llm", "--json"};
  testing::Invocation recorded, replayed;
  {
    FakeLlmServer server(ServerMode::kModel, plausible_goals());
    auto record = args;
    record.insert(record.end(), {"--transcript", (dir_ / "recorded").string(), "--llm",
                                 "record:" + cassette + ",openai:" + server.url()});
    recorded = testing::run_cli(record, dir_);
  }
  auto replay = args;
  replay.insert(replay.end(), {"--transcript", (dir_ / "replayed").string(), "--llm", "replay:" + cassette});
  replayed = testing::run_cli(replay, dir_);
  ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  auto a = nlohmann::json::parse(recorded.out), b = nlohmann::json::parse(replayed.out);
  ASSERT_EQ(a.size(), 1u);
  a[0].erase("wall_ms");
  b[0].erase("wall_ms");
  EXPECT_EQ(a, b);
  EXPECT_GT(a[0]["llm_calls"].get<int>(), 0);
  const std::string transcript = testing::read_text(dir_ / "recorded" / "inst+search2+llm.txt");
  EXPECT_THAT(transcript, HasSubstr("[LM] For a ketchup on the table, is the goal that"));
  EXPECT_EQ(testing::read_text(dir_ / "replayed" / "inst+search2+llm.txt"), transcript);
}

// With several conditions each keeps its own cassette (FILE's name with
// ".<condition>" inserted), so a replay of every condition is exact.
TEST_F(RecordReplay, OneCassetteForSeveralConditionsReplaysEach) {
  const std::string cassette = (dir_ / "run.jsonl").string();
  std::vector<std::string> args = {"experiment", "--scenario", source_path("data/scenarios/tidy-kitchen.yaml").string(),
                                   "--conditions", "inst+llm,inst+search4+llm", "--json"};
  testing::Invocation recorded, replayed;
  {
    FakeLlmServer server(ServerMode::kModel, plausible_goals());
    auto record = args;
    record.insert(record.end(), {"--llm", "record:" + cassette + ",openai:" + server.url()});
    recorded = testing::run_cli(record, dir_);
  }
  auto replay = args;
  replay.insert(replay.end(), {"--llm", "replay:" + cassette});
  replayed = testing::run_cli(replay, dir_);
  ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  auto a = nlohmann::json::parse(recorded.out), b = nlohmann::json::parse(replayed.out);
  for (auto* all : {&a, &b})
    for (auto& r : *all) r.erase("wall_ms");
  EXPECT_EQ(a, b);

  // Re-recording the replay (record:NEW,replay:OLD) keeps one cassette per
  // condition on both sides, and gives the same cassettes to the byte.
  const std::string again = (dir_ / "again.jsonl").string();
  auto rerecord = args;
  rerecord.insert(rerecord.end(), {"--llm", "record:" + again + ",replay:" + cassette});
  testing::Invocation rerecorded = testing::run_cli(rerecord, dir_);
  ASSERT_EQ(rerecorded.exit_code, 0) << rerecorded.err;
  auto c = nlohmann::json::parse(rerecorded.out);
  for (auto& r : c) r.erase("wall_ms");
  EXPECT_EQ(c, a);
  for (const std::string condition : {"inst+llm", "inst+search4+llm"}) {
    const std::string first = testing::read_text(dir_ / ("run." + condition + ".jsonl"));
    EXPECT_FALSE(first.empty()) << condition;
    EXPECT_EQ(testing::read_text(dir_ / ("again." + condition + ".jsonl")), first) << condition;
  }
}

}  // namespace
}  // namespace apprentice
