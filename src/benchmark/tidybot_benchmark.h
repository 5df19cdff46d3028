// The TidyBot benchmark run through the real agent (`apprentice benchmark
// tidybot`). Each scenario is one person; nothing carries over from one
// scenario to the next. Two protocols, each in several settings:
//
//  - Protocol A, examples then new objects: the simulated teacher teaches
//    the task and the seen placements in a world holding the seen objects
//    (inst+search4). Then, in a world holding the unseen objects, the agent
//    places them with what it learned: alone (no one answers questions
//    about things), alone with the LLM, or with the teacher (who answers
//    every question; everything should be right in the end, with few
//    questions).
//  - Protocol B, the person's rule: in a world holding every object, the
//    person says the annotator's note once; alone, before the task (at the
//    first question about its steps), then no one answers about things;
//    with the teacher, at the first question about where a thing goes, and
//    the teacher answers the rest.
//
// Each object ends right (where the person wants it), wrong (moved
// elsewhere) or left (still on the cart). Questions are those the agent
// asked about things.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "benchmark/tidybot_scenarios.h"
#include "llm/llm_client.h"
#include "llm/placement_corpus.h"
#include "util/result.h"

namespace apprentice::benchmark {

enum class Protocol { kExamples, kNote };  // A, B

struct Setting {
  std::string name;  // "a-alone", "a-alone+llm", "a-teacher", "b-alone", ...
  Protocol protocol = Protocol::kExamples;
  bool teacher = false;  // a teacher answers questions about things
  bool llm = false;
};

// Every setting, in the order tables print them.
std::vector<Setting> all_settings();
// Parses a setting's name; kInvalidInput listing the names otherwise.
Result<Setting> parse_setting(std::string_view name);

struct Tally {
  int right = 0;
  int wrong = 0;
  int left = 0;
  int questions = 0;     // questions about things
  int instructions = 0;  // everything the teacher said in the measured sessions
  int objects() const { return right + wrong + left; }
  Tally& operator+=(const Tally& other);
};

struct ObjectOutcome {
  std::string object;  // the benchmark's name
  std::string wanted;  // the receptacle the person wants
  std::string placed;  // where it ended; empty when still on the cart
  bool unseen = false;  // one of the scenario's unseen objects
  // The receptacle the agent's sources believed most before anyone
  // answered, and that belief (agent's ObjectReport::proposed, belief);
  // "" and 0 when nothing was proposed (or its goal was known).
  std::string proposed;
  double belief = 0;
};

struct ScenarioOutcome {
  int index = 0;
  std::vector<std::string> tags;
  Tally tally;
  Tally unseen;  // of the unseen objects only (protocol A: all of them)
  std::vector<ObjectOutcome> objects;
  std::string transcript;  // the measured session's dialogue
};

struct SettingResult {
  Setting setting;
  Tally total;
  std::map<std::string, Tally> by_tag;  // a scenario counts under each of its tags
  std::vector<ScenarioOutcome> scenarios;
  // The mean over scenarios of each one's share right: how TidyBot reports
  // accuracy (the pooled share is total.right / total.objects()); and the
  // same of the unseen objects alone, what TidyBot's figures are about.
  double mean_scenario_percent = 0;
  Tally unseen;
  double mean_unseen_percent = 0;
  int llm_calls = 0;
  int llm_failures = 0;
  double wall_ms = 0;
};

// Calibration: had the agent acted alone on every thing whose belief is at
// least `threshold` and asked about the rest, how many of the things it
// measures (protocol A: the unseen; B: all) it would have placed right,
// wrong, and asked about. From each thing's first belief in the setting.
struct CurvePoint {
  double threshold = 0;
  int right = 0;
  int wrong = 0;
  int asked = 0;
};
std::vector<CurvePoint> calibration_curve(const SettingResult& result);

// Makes a fresh LLM client; one per setting that uses the LLM.
using LlmClientFactory = std::function<Result<std::unique_ptr<llm::LlmClient>>()>;

struct BenchmarkOptions {
  std::vector<Setting> settings;  // empty: every setting that can run
  LlmClientFactory llm;           // unset: the settings with an LLM are skipped
  std::filesystem::path prompts_dir;  // data/prompts
  std::filesystem::path domain;       // data/domains/kitchen.pddl
  bool keep_transcripts = false;
  // TidyBot's own recorded answers (llm-dev.jsonl), to set their scores
  // beside ours, per tag (score_recorded_answers); none: not shown.
  std::vector<llm::RecordedAnswer> recorded_answers;
};

// TidyBot's recorded answers on these scenarios, scored as TidyBot scores
// them: for each method, each scenario's share of its unseen objects
// placed right by that method's answer for them, the mean over the
// scenarios that have one, overall and per tag.
struct RecordedScore {
  std::string method;  // summarization, human-summary, examples-only, commonsense
  int scenarios = 0;
  double mean_percent = 0;
  std::map<std::string, double> by_tag;
};
std::vector<RecordedScore> score_recorded_answers(const std::vector<TidyBotScenario>& scenarios,
                                                  const std::vector<llm::RecordedAnswer>& answers);

struct BenchmarkResults {
  std::vector<SettingResult> results;  // in the order of the settings
  std::vector<std::string> skipped;    // settings left out for want of an LLM
  std::vector<RecordedScore> recorded;  // with BenchmarkOptions::recorded_answers
};

// Errors: kInvalidInput for a setting with an LLM but no `llm`; a world
// that cannot be built (naming the scenario); the LLM factory's and the
// prompt templates' errors; the agent's, prefixed with the scenario.
Result<BenchmarkResults> run_tidybot(const std::vector<TidyBotScenario>& scenarios, const BenchmarkOptions& options);

// Accuracy TidyBot published on the whole benchmark (96 scenarios; Wu et
// al. 2023), by method, in percent of the unseen objects (mean over
// scenarios).
struct PublishedFigure {
  const char* method;
  double percent;
};
const std::vector<PublishedFigure>& tidybot_published();

// The table `apprentice benchmark tidybot` prints, and its --json.
std::string format_tidybot_table(const BenchmarkResults& results);
std::string tidybot_json(const BenchmarkResults& results);

}  // namespace apprentice::benchmark
