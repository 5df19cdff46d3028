// The benchmark run through the agent on two small scenarios written here:
// what each setting counts, and what must hold whatever the agent learns
// (every object counted once; with the teacher, everything right).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "benchmark/tidybot_benchmark.h"
#include <fstream>
#include <optional>
#include <string>

#include "common/paths.h"
#include "common/scratch.h"
#include "llm/factory.h"
#include "tidybot_fixtures.h"

namespace apprentice::benchmark {
namespace {

using ::testing::HasSubstr;

class TidyBotRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
    ASSERT_TRUE(scenarios) << scenarios.error().describe();
    BenchmarkOptions options;
    options.prompts_dir = apprentice::testing::source_path("data/prompts");
    options.domain = apprentice::testing::source_path("data/domains/kitchen.pddl");
    options.keep_transcripts = true;
    auto results = run_tidybot(*scenarios, options);
    ASSERT_TRUE(results) << results.error().describe();
    results_ = new BenchmarkResults(std::move(*results));
  }
  static void TearDownTestSuite() {
    delete results_;
    results_ = nullptr;
  }
  static const SettingResult& setting(std::string_view name) {
    for (const SettingResult& r : results_->results)
      if (r.setting.name == name) return r;
    ADD_FAILURE() << "no setting " << name;
    return results_->results.front();
  }
  static BenchmarkResults* results_;
};

BenchmarkResults* TidyBotRun::results_ = nullptr;

TEST_F(TidyBotRun, WithoutAnLlmTheLlmSettingsAreSkipped) {
  ASSERT_NE(results_, nullptr);
  EXPECT_EQ(results_->results.size(), 4u);
  EXPECT_THAT(results_->skipped, ::testing::ElementsAre("a-alone+llm", "a-teacher+llm", "b-alone+llm"));
}

TEST_F(TidyBotRun, EveryObjectIsCountedOnce) {
  ASSERT_NE(results_, nullptr);
  for (const SettingResult& r : results_->results) {
    const int objects = r.setting.protocol == Protocol::kExamples ? 4 : 8;
    EXPECT_EQ(r.total.objects(), objects) << r.setting.name;
    ASSERT_EQ(r.scenarios.size(), 2u);
    EXPECT_EQ(r.scenarios[0].index, 7);
    int placements = 0;
    for (const ScenarioOutcome& s : r.scenarios) placements += static_cast<int>(s.objects.size());
    EXPECT_EQ(placements, objects) << r.setting.name;
    // The second scenario alone has the tag attribute.
    EXPECT_EQ(r.by_tag.at("attribute").objects(), r.scenarios[1].tally.objects()) << r.setting.name;
    EXPECT_EQ(r.by_tag.at("category").objects(), objects) << r.setting.name;
  }
}

TEST_F(TidyBotRun, WithTheTeacherEverythingEndsRight) {
  ASSERT_NE(results_, nullptr);
  for (const char* name : {"a-teacher", "b-teacher"}) {
    const SettingResult& r = setting(name);
    EXPECT_EQ(r.total.right, r.total.objects()) << name;
    EXPECT_EQ(r.total.wrong, 0) << name;
    EXPECT_DOUBLE_EQ(r.mean_scenario_percent, 100.0) << name;
    for (const ScenarioOutcome& s : r.scenarios)
      for (const ObjectOutcome& o : s.objects) EXPECT_EQ(o.placed, o.wanted) << name << ": " << o.object;
  }
}

TEST_F(TidyBotRun, AKindTaughtByTheExamplesNeedsNoQuestion) {
  ASSERT_NE(results_, nullptr);
  // "polo shirt 2" is another polo shirt, whose place was shown.
  const SettingResult& alone = setting("a-alone");
  const ObjectOutcome& second_shirt = alone.scenarios[0].objects[2];
  EXPECT_EQ(second_shirt.object, "polo shirt 2");
  EXPECT_EQ(second_shirt.placed, "hamper");
  EXPECT_EQ(alone.total.questions, 0) << "alone, nobody is asked";
  // With the teacher, only the three new kinds may be asked about.
  EXPECT_LE(setting("a-teacher").total.questions, 3);
}

TEST_F(TidyBotRun, TheNoteIsSaidInThePersonsWords) {
  ASSERT_NE(results_, nullptr);
  const std::string& alone = setting("b-alone").scenarios[0].transcript;
  const std::string& taught = setting("b-teacher").scenarios[0].transcript;
  const std::string note = "Instructor: Put shirts in the hamper and blocks in the toy chest.";
  EXPECT_THAT(alone, HasSubstr(note));
  EXPECT_THAT(taught, HasSubstr(note));
  // Alone it comes before the task's steps; with the teacher at the first
  // question about where a thing goes.
  EXPECT_LT(alone.find(note), alone.find("Repeat the following tasks"));
  EXPECT_GT(taught.find(note), taught.find("Where should"));
}

TEST_F(TidyBotRun, TheJsonHasTheCountsOfEachSetting) {
  ASSERT_NE(results_, nullptr);
  auto json = nlohmann::json::parse(tidybot_json(*results_));
  ASSERT_EQ(json["settings"].size(), 4u);
  for (const auto& s : json["settings"]) {
    for (const char* key : {"objects", "right", "wrong", "left", "questions", "instructions", "llm_calls"})
      EXPECT_TRUE(s[key].is_number_integer()) << key;
    EXPECT_EQ(s["right"].get<int>() + s["wrong"].get<int>() + s["left"].get<int>(), s["objects"].get<int>());
    EXPECT_TRUE(s["by_tag"].contains("attribute"));
    EXPECT_EQ(s["scenarios"].size(), 2u);
  }
  EXPECT_EQ(json["tidybot_published"].size(), tidybot_published().size());
  const std::string table = format_tidybot_table(*results_);
  EXPECT_THAT(table, HasSubstr("a-alone"));
  EXPECT_THAT(table, HasSubstr("CLIP embeddings 83.7%"));
  EXPECT_THAT(table, HasSubstr("Skipped for want of an LLM: a-alone+llm"));
}

// The LLM settings with answers recorded for the two scenarios: a summary
// asked of the seen placements and placements by it (protocol A), and
// placements by the person's note (protocol B).
TEST(TidyBotWithAnLlm, TheLlmsPlacementsAreWeighedAgainstTheExamplesAndTheRule) {
  apprentice::testing::ScratchDir scratch;
  const auto corpus = scratch / "answers.jsonl";
  std::ofstream(corpus) << testing::kTwoScenariosAnswers;
  auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
  ASSERT_TRUE(scenarios);
  BenchmarkOptions options;
  options.prompts_dir = apprentice::testing::source_path("data/prompts");
  options.domain = apprentice::testing::source_path("data/domains/kitchen.pddl");
  options.llm = [corpus] { return llm::make_llm_client("corpus:" + corpus.string(), llm::LlmOptions{}); };
  for (const char* name : {"a-alone+llm", "a-teacher+llm", "b-alone+llm"}) options.settings.push_back(*parse_setting(name));
  auto results = run_tidybot(*scenarios, options);
  ASSERT_TRUE(results) << results.error().describe();
  const SettingResult& alone = results->results[0];
  // The shirt and the block as the LLM placed them, the second polo shirt
  // by what was taught. The LLM put the coffee mug (wrongly) on the bottom
  // shelf; the examples say it is like the Disney mug, and the decision
  // weighs both: it does not act on the LLM's word alone.
  EXPECT_EQ(alone.total.right + alone.total.left, 4);
  EXPECT_EQ(alone.total.wrong, 0);
  EXPECT_NE(alone.scenarios[1].objects[0].placed, "bottom shelf");
  EXPECT_EQ(alone.scenarios[1].objects[0].proposed, "top shelf");
  EXPECT_EQ(alone.total.questions, 0);
  EXPECT_GT(alone.llm_calls, 0);
  const SettingResult& taught = results->results[1];
  EXPECT_EQ(taught.total.right, 4);
  EXPECT_EQ(taught.total.wrong, 0);
  // By the note, which is word for word the summary: every object, the
  // seen from the answer recorded by the note, the unseen from the one
  // recorded by the summary (the same rule, so the same query).
  const SettingResult& note = results->results[2];
  EXPECT_EQ(note.scenarios[0].tally.right, 5);
  EXPECT_EQ(note.scenarios[1].tally.right, 2);
  EXPECT_EQ(note.scenarios[1].tally.wrong, 0) << "the person said mugs go on the top shelf";
}

// The LLM is asked twice more beside its summary's placements: its summary
// given back to it with the things taught (does it put them back where they
// were taught?), and the new things with the examples alone. A summary that
// loses an example makes its placements less sure; a placement from the
// examples that disagrees makes the thing less sure.
TEST(TidyBotWithAnLlm, ASummaryThatLosesAnExampleIsTrustedLess) {
  auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
  ASSERT_TRUE(scenarios);
  scenarios->resize(1);  // the shirts and the blocks
  const std::string summary =
      R"({"scenario": 7, "method": "summarization", "step": "summary", "receptacles": ["hamper", "toy chest"], "examples": [["polo shirt", "hamper"], ["wooden block", "toy chest"]], "completion": "", "summary": "Put shirts in the hamper and blocks in the toy chest."})"
      "\n"
      R"({"scenario": 7, "method": "summarization", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["flannel shirt", "foam block", "polo shirt 2"], "completion": "", "placements": [["flannel shirt", "hamper"], ["foam block", "toy chest"], ["polo shirt 2", "hamper"]]})"
      "\n";
  auto back = [](const char* shirt_goes) {
    return std::string(
               R"({"scenario": 7, "method": "summarization", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["polo shirt", "wooden block"], "completion": "", "placements": [["polo shirt", ")") +
           shirt_goes + R"("], ["wooden block", "toy chest"]]})" "\n";
  };
  const std::string by_examples =
      R"({"scenario": 7, "method": "examples-only", "step": "placement", "receptacles": ["hamper", "toy chest"], "examples": [["polo shirt", "hamper"], ["wooden block", "toy chest"]], "objects": ["flannel shirt", "foam block", "polo shirt 2"], "completion": "", "placements": [["flannel shirt", "hamper"], ["foam block", "hamper"], ["polo shirt 2", "hamper"]]})"
      "\n";
  apprentice::testing::ScratchDir scratch;
  auto run = [&](const std::string& name, const std::string& answers) -> SettingResult {
    const auto corpus = scratch / (name + ".jsonl");
    std::ofstream(corpus) << answers;
    BenchmarkOptions options;
    options.prompts_dir = apprentice::testing::source_path("data/prompts");
    options.domain = apprentice::testing::source_path("data/domains/kitchen.pddl");
    options.llm = [corpus] { return llm::make_llm_client("corpus:" + corpus.string(), llm::LlmOptions{}); };
    options.settings = {*parse_setting("a-alone+llm")};
    auto results = run_tidybot(*scenarios, options);
    EXPECT_TRUE(results) << results.error().describe();
    return results ? results->results.front() : SettingResult{};
  };
  const SettingResult keeps = run("keeps", summary + back("hamper"));
  const SettingResult loses = run("loses", summary + back("toy chest"));
  const SettingResult disagrees = run("disagrees", summary + back("hamper") + by_examples);
  for (const SettingResult* r : {&keeps, &loses, &disagrees}) {
    ASSERT_EQ(r->scenarios.size(), 1u);
    ASSERT_EQ(r->scenarios[0].objects.size(), 3u);
    EXPECT_EQ(r->total.wrong, 0);
  }
  // The flannel shirt: the same sources but the LLM's, which is surer when
  // its summary kept the examples.
  EXPECT_EQ(keeps.scenarios[0].objects[0].proposed, "hamper");
  EXPECT_LT(loses.scenarios[0].objects[0].belief, keeps.scenarios[0].objects[0].belief);
  // The foam block: the examples alone put it in the hamper.
  EXPECT_EQ(disagrees.scenarios[0].objects[1].proposed, "toy chest");
  EXPECT_LT(disagrees.scenarios[0].objects[1].belief, keeps.scenarios[0].objects[1].belief);
}

TEST(TidyBotRecorded, TidyBotsOwnAnswersAreScoredAsItScoresThem) {
  apprentice::testing::ScratchDir scratch;
  const auto corpus = scratch / "answers.jsonl";
  std::ofstream(corpus) << testing::kTwoScenariosAnswers;
  auto answers = llm::read_recorded_answers(corpus);
  ASSERT_TRUE(answers) << answers.error().describe();
  auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
  ASSERT_TRUE(scenarios);
  std::vector<RecordedScore> scores = score_recorded_answers(*scenarios, *answers);
  // Only the summarization has answers for the unseen objects: all three
  // of the first scenario right, the coffee mug of the second wrong.
  ASSERT_EQ(scores.size(), 1u);
  EXPECT_EQ(scores[0].method, "summarization");
  EXPECT_EQ(scores[0].scenarios, 2);
  EXPECT_DOUBLE_EQ(scores[0].mean_percent, 50.0);
  EXPECT_DOUBLE_EQ(scores[0].by_tag.at("category"), 50.0);
  EXPECT_DOUBLE_EQ(scores[0].by_tag.at("attribute"), 0.0);
}

// On the development half, the figures its README gives for the recorded
// answers.
TEST(TidyBotRecorded, TheDevelopmentHalfScoresAsItsReadmeSays) {
  const auto scenarios_path = apprentice::testing::shared_path("data/tidybot-benchmark/scenarios-dev.yml");
  const auto corpus_path = apprentice::testing::shared_path("data/tidybot-benchmark/llm-dev.jsonl");
  APPRENTICE_REQUIRE_SHARED(scenarios_path);
  APPRENTICE_REQUIRE_SHARED(corpus_path);
  auto scenarios = load_tidybot_scenarios(scenarios_path);
  auto answers = llm::read_recorded_answers(corpus_path);
  ASSERT_TRUE(scenarios && answers);
  std::map<std::string, double> mean;
  for (const RecordedScore& score : score_recorded_answers(*scenarios, *answers)) {
    EXPECT_EQ(score.scenarios, 48) << score.method;
    mean[score.method] = score.mean_percent;
  }
  EXPECT_NEAR(mean["summarization"], 90.0, 0.05);
  EXPECT_NEAR(mean["human-summary"], 96.8, 0.05);
  EXPECT_NEAR(mean["examples-only"], 74.8, 0.05);
  EXPECT_NEAR(mean["commonsense"], 45.4, 0.05);
}

// A person's class rule goes only to the things in its class. A nursery,
// written here after a teach dialogue where "dummy goes in the top drawer"
// was offered for the rattle, the teddy bear, the blanket and the board
// book ("Does the rattle ... go as you said: it goes in the top drawer?";
// now "go with dummies, as you said"):
// nothing says any of them is a dummy.
// Protocol B alone and with the teacher (b-alone, b-teacher) on scenarios
// in the benchmark's format; nullopt (a failure added) when they do not run.
std::optional<BenchmarkResults> run_protocol_b(const std::string& yaml) {
  auto scenarios = parse_tidybot_scenarios(yaml, "written-here.yml");
  if (!scenarios) {
    ADD_FAILURE() << scenarios.error().describe();
    return std::nullopt;
  }
  BenchmarkOptions options;
  options.prompts_dir = apprentice::testing::source_path("data/prompts");
  options.domain = apprentice::testing::source_path("data/domains/kitchen.pddl");
  options.keep_transcripts = true;
  for (const char* name : {"b-alone", "b-teacher"}) options.settings.push_back(*parse_setting(name));
  auto results = run_tidybot(*scenarios, options);
  if (!results) {
    ADD_FAILURE() << results.error().describe();
    return std::nullopt;
  }
  return std::move(*results);
}

// The note said as the answer to where the first thing goes: kept as a
// rule (though "clothes" alone would name the skirt, the only kind here
// WordNet puts under it by that word), and the thing asked about is placed
// by it, not asked about again.
TEST(TidyBotPersonsRule, ANoteSaidWhereAThingGoesPlacesIt) {
  const std::string bedroom = R"(- annotator_notes: Put clothes in the hamper and toys in the toy box.
  benchmark_index: 5
  receptacles:
  - hamper
  - toy box
  room: bedroom
  seen_objects:
  - skirt
  - toy car
  seen_placements:
  - - skirt
    - hamper
  - - toy car
    - toy box
  tags:
  - category
  unseen_objects:
  - jeans
  - toy train
  unseen_placements:
  - - jeans
    - hamper
  - - toy train
    - toy box
)";
  auto results = run_protocol_b(bedroom);
  ASSERT_TRUE(results);
  ASSERT_EQ(results->results.size(), 2u);
  const ScenarioOutcome& taught = results->results[1].scenarios[0];
  EXPECT_THAT(taught.transcript, HasSubstr("So clothes go in the hamper and toys go in the toy box.")) << taught.transcript;
  const std::string first = "Where should the skirt on the cart go?";
  const std::size_t asked = taught.transcript.find(first);
  ASSERT_NE(asked, std::string::npos) << taught.transcript;
  EXPECT_EQ(taught.transcript.find(first, asked + 1), std::string::npos) << taught.transcript;
  for (const ObjectOutcome& o : taught.objects) {
    if (o.object != "skirt") continue;
    EXPECT_EQ(o.placed, "hamper");
  }
}

// A "no" to a yes/no about one thing is followed by where it goes, not by
// a second guess (docs/benchmarks.md, "After a no, where").
TEST(TidyBotPersonsRule, AfterANoTheTeacherIsAskedWhere) {
  const std::string garage = R"(- annotator_notes: Put heavy items on the bottom shelf and light items on the top shelf.
  benchmark_index: 7
  receptacles:
  - top shelf
  - bottom shelf
  - basket
  room: garage
  seen_objects:
  - dumbbell
  - feather
  seen_placements:
  - - dumbbell
    - bottom shelf
  - - feather
    - top shelf
  tags:
  - attribute
  unseen_objects:
  - brick
  - paper towel
  - bowling ball
  - balloon
  - tire
  - sponge
  unseen_placements:
  - - brick
    - bottom shelf
  - - paper towel
    - top shelf
  - - bowling ball
    - bottom shelf
  - - balloon
    - top shelf
  - - tire
    - bottom shelf
  - - sponge
    - top shelf
)";
  auto results = run_protocol_b(garage);
  ASSERT_TRUE(results);
  ASSERT_EQ(results->results.size(), 2u);
  const std::string& taught = results->results[1].scenarios[0].transcript;
  const std::string no = "Instructor: no.\n";
  std::size_t noes = 0;
  for (std::size_t at = taught.find(no); at != std::string::npos; at = taught.find(no, at + 1)) {
    ++noes;
    EXPECT_EQ(taught.compare(at + no.size(), 19, "Agent: Where should"), 0) << taught.substr(at, 200);
  }
  // The vectors alone tell heavy from light: some guess is refused.
  EXPECT_GT(noes, 0u) << taught;
}

TEST(TidyBotPersonsRule, AClassRuleIsNotOfferedForThingsOutsideItsClass) {
  const std::string nursery = R"(- annotator_notes: Dummies go in the top drawer.
  benchmark_index: 3
  receptacles:
  - top drawer
  - bottom drawer
  - toy basket
  - shelf
  room: nursery
  seen_objects:
  - pacifier
  - rattle
  seen_placements:
  - - pacifier
    - top drawer
  - - rattle
    - toy basket
  tags:
  - category
  unseen_objects:
  - teddy bear
  - blanket
  - board book
  unseen_placements:
  - - teddy bear
    - toy basket
  - - blanket
    - bottom drawer
  - - board book
    - shelf
)";
  auto results = run_protocol_b(nursery);
  ASSERT_TRUE(results);
  ASSERT_EQ(results->results.size(), 2u);
  const std::string& taught = results->results[1].scenarios[0].transcript;
  ASSERT_THAT(taught, HasSubstr("Dummies go in the top drawer.")) << taught;
  for (const char* thing : {"rattle", "teddy bear", "blanket", "board book"}) {
    EXPECT_THAT(taught, ::testing::Not(HasSubstr("Does the " + std::string(thing) + " on the cart go with dummies")))
        << taught;
    for (const SettingResult& r : results->results) {
      for (const ObjectOutcome& o : r.scenarios[0].objects) {
        if (o.object == thing) {
          EXPECT_NE(o.placed, "top drawer") << r.setting.name << ": " << thing;
        }
      }
    }
  }
}

TEST(TidyBotSettings, ASettingWithAnLlmNeedsOne) {
  auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
  ASSERT_TRUE(scenarios);
  BenchmarkOptions options;
  options.settings = {*parse_setting("a-alone+llm")};
  options.domain = apprentice::testing::source_path("data/domains/kitchen.pddl");
  auto results = run_tidybot(*scenarios, options);
  ASSERT_FALSE(results);
  EXPECT_EQ(results.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(results.error().message, HasSubstr("needs an LLM"));
  auto unknown = parse_setting("c-alone");
  ASSERT_FALSE(unknown);
  EXPECT_THAT(unknown.error().message, HasSubstr("a-alone, a-alone+llm"));
}

}  // namespace
}  // namespace apprentice::benchmark
