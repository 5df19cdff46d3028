#include "benchmark/tidybot_benchmark.h"

#include <algorithm>
#include <set>

#include "agent/agent.h"
#include "face/apprentice.h"
#include "benchmark/tidybot_teacher.h"
#include "benchmark/tidybot_world.h"
#include "language/generation.h"
#include "llm/prompts.h"
#include "util/text.h"

namespace apprentice::benchmark {

std::vector<Setting> all_settings() {
  return {
      {"a-alone", Protocol::kExamples, false, false},   {"a-alone+llm", Protocol::kExamples, false, true},
      {"a-teacher", Protocol::kExamples, true, false},  {"a-teacher+llm", Protocol::kExamples, true, true},
      {"b-alone", Protocol::kNote, false, false},       {"b-alone+llm", Protocol::kNote, false, true},
      {"b-teacher", Protocol::kNote, true, false},
  };
}

Result<Setting> parse_setting(std::string_view name) {
  std::string names;
  for (const Setting& setting : all_settings()) {
    if (setting.name == name) return setting;
    names += (names.empty() ? "" : ", ") + setting.name;
  }
  return make_error(ErrorCode::kInvalidInput,
                    "unknown setting " + apprentice::quoted(name) + " (expected one of: " + names + ")");
}

Tally& Tally::operator+=(const Tally& other) {
  right += other.right;
  wrong += other.wrong;
  left += other.left;
  questions += other.questions;
  instructions += other.instructions;
  return *this;
}

const std::vector<PublishedFigure>& tidybot_published() {
  static const std::vector<PublishedFigure> kFigures = {
      {"LLM summarization", 91.2},
      {"CLIP embeddings", 83.7},
      {"LLM, examples only", 78.5},
      {"LLM, the human-written note", 97.5},
  };
  return kFigures;
}

namespace {

// What every session of one run shares.
struct Bench {
  const BenchmarkOptions& options;
  language::Lexicon lexicon = language::Lexicon::open_default();
  std::map<int, Knowledge> taught;  // protocol A: what each scenario's seen placements taught
};

Condition condition_for(bool teacher, bool llm) {
  Condition condition;
  condition.name = std::string(teacher ? "inst+" : "") + "search4" + (llm ? "+llm" : "");
  condition.instruction = teacher;
  condition.search_depth = 4;
  condition.llm = llm;
  return condition;
}

struct Session {
  Knowledge knowledge;  // what the agent knows at the end
  State end;
  std::map<std::string, std::size_t> reports;  // report.objects' index by the world's name of the object
  AgentReport report;
  Tally tally;          // questions and instructions only
  std::string transcript;
};

// One learning session of the agent in `world`, from `knowledge`, with the
// benchmark's teacher.
Result<Session> run_session(const BenchmarkWorld& world, Knowledge knowledge, const Condition& condition,
                            const TeacherOptions& teaching, LlmAdvisor* advisor) {
  AgentSpec spec = default_agent_spec();
  spec.condition = condition.name;
  spec.condition_parts = condition;
  spec.start_from = std::make_shared<const Knowledge>(std::move(knowledge));
  spec.lent_advisor = advisor;  // one advisor for the whole run: its counts and its breaker
  auto agent = make_agent_session(spec, world.scenario);
  if (!agent) return tl::unexpected(agent.error());
  BenchmarkTeacher teacher(world.scenario, teaching);
  auto report = (*agent)->learn(teacher);
  if (!report) return tl::unexpected(report.error());
  if (report->stopped) return make_error(ErrorCode::kCancelled, report->stop_reason);
  Session session{(*agent)->knowledge(), report->end, {}, report->agent, {}, report->transcript};
  for (std::size_t i = 0; i < session.report.objects.size(); ++i) session.reports.emplace(session.report.objects[i].object, i);
  session.tally.questions = teacher.questions_about_things();
  session.tally.instructions = report->counts.instructions;
  return session;
}

// Where each object ended, against where the person wants it.
std::vector<ObjectOutcome> outcomes(const BenchmarkWorld& world, const TidyBotScenario& scenario, const Session& session,
                                    Tally& tally, Tally& unseen) {
  World now = world.scenario.world;
  now.state = session.end;
  std::vector<ObjectOutcome> out;
  for (const auto& [name, id] : world.objects) {
    ObjectOutcome outcome;
    outcome.object = name;
    const std::string& category = world.scenario.world.universe->info(id).category;
    if (const IntentEntry* entry = world.scenario.find_intent("clear", category))
      outcome.wanted = world.receptacle_name(entry->place);
    auto place = language::place_of(now, id);
    if (place && *place != world.cart) outcome.placed = world.receptacle_name(*place);
    if (auto r = session.reports.find(now.universe->name(id)); r != session.reports.end()) {
      const ObjectReport& report = session.report.objects[r->second];
      if (auto at = now.universe->find(report.proposed); at && !report.proposed.empty())
        outcome.proposed = world.receptacle_name(*at);
      outcome.belief = report.belief;
    }
    outcome.unseen = std::find(scenario.unseen_objects.begin(), scenario.unseen_objects.end(), name) !=
                     scenario.unseen_objects.end();
    for (Tally* counted : {&tally, outcome.unseen ? &unseen : nullptr}) {
      if (counted == nullptr) continue;
      if (outcome.placed.empty()) ++counted->left;
      else if (outcome.placed == outcome.wanted) ++counted->right;
      else ++counted->wrong;
    }
    out.push_back(std::move(outcome));
  }
  return out;
}

std::vector<std::string> all_objects(const TidyBotScenario& scenario) {
  std::vector<std::string> objects = scenario.seen_objects;
  objects.insert(objects.end(), scenario.unseen_objects.begin(), scenario.unseen_objects.end());
  return objects;
}

// Protocol A's first part: the seen placements taught in a world of the
// seen objects, from nothing (kept for every setting of protocol A).
Result<Knowledge> taught_examples(Bench& bench, const TidyBotScenario& scenario) {
  if (auto known = bench.taught.find(scenario.index); known != bench.taught.end()) return known->second;
  auto world = build_world(scenario, scenario.seen_objects, bench.options.domain, bench.lexicon);
  if (!world) return tl::unexpected(world.error());
  auto session = run_session(*world, Knowledge{}, condition_for(true, false), TeacherOptions{}, nullptr);
  if (!session) return tl::unexpected(session.error());
  return bench.taught.emplace(scenario.index, std::move(session->knowledge)).first->second;
}

Result<ScenarioOutcome> run_scenario(Bench& bench, const TidyBotScenario& scenario, const Setting& setting,
                                     LlmAdvisor* advisor) {
  Knowledge knowledge;
  TeacherOptions teaching;
  teaching.answers_about_things = setting.teacher;
  std::vector<std::string> objects;
  if (setting.protocol == Protocol::kExamples) {
    auto taught = taught_examples(bench, scenario);
    if (!taught) return tl::unexpected(taught.error());
    knowledge = *taught;
    objects = scenario.unseen_objects;
  } else {
    teaching.note = scenario.note;
    teaching.note_at = setting.teacher ? NoteAt::kGoalQuestion : NoteAt::kTaskStep;
    objects = all_objects(scenario);
  }
  auto world = build_world(scenario, objects, bench.options.domain, bench.lexicon);
  if (!world) return tl::unexpected(world.error());
  auto session = run_session(*world, std::move(knowledge), condition_for(setting.teacher, setting.llm), teaching, advisor);
  if (!session) return tl::unexpected(session.error());
  ScenarioOutcome outcome;
  outcome.index = scenario.index;
  outcome.tags = scenario.tags;
  outcome.tally = session->tally;
  outcome.objects = outcomes(*world, scenario, *session, outcome.tally, outcome.unseen);
  if (bench.options.keep_transcripts) outcome.transcript = std::move(session->transcript);
  return outcome;
}

Result<std::unique_ptr<LlmAdvisor>> make_advisor(const BenchmarkOptions& options, const Setting& setting) {
  auto client = options.llm();
  if (!client) return tl::unexpected(client.error());
  auto templates = llm::PromptTemplates::load(options.prompts_dir);
  if (!templates) return tl::unexpected(templates.error());
  auto preferences = llm::PreferencePrompts::load(options.prompts_dir);
  if (!preferences) return tl::unexpected(preferences.error());
  LlmAdvisorOptions advice;
  advice.instructed = setting.teacher;
  auto advisor = std::make_unique<LlmAdvisor>(std::move(*client), std::move(*templates), advice);
  advisor->set_preference_prompts(std::move(*preferences));
  return advisor;
}

Result<SettingResult> run_setting(Bench& bench, const std::vector<TidyBotScenario>& scenarios, const Setting& setting) {
  const auto started = std::chrono::steady_clock::now();
  std::unique_ptr<LlmAdvisor> advisor;
  if (setting.llm) {
    if (!bench.options.llm)
      return make_error(ErrorCode::kInvalidInput, "setting " + setting.name + " needs an LLM: pass --llm SPEC");
    auto made = make_advisor(bench.options, setting);
    if (!made) return tl::unexpected(made.error());
    advisor = std::move(*made);
  }
  SettingResult result;
  result.setting = setting;
  double percent_sum = 0, unseen_sum = 0;
  for (const TidyBotScenario& scenario : scenarios) {
    auto outcome = run_scenario(bench, scenario, setting, advisor.get());
    if (!outcome)
      return tl::unexpected(prefix_error(outcome.error(), "TidyBot scenario " + std::to_string(scenario.index)));
    result.total += outcome->tally;
    for (const std::string& tag : scenario.tags) result.by_tag[tag] += outcome->tally;
    result.unseen += outcome->unseen;
    if (outcome->tally.objects() > 0) percent_sum += 100.0 * outcome->tally.right / outcome->tally.objects();
    if (outcome->unseen.objects() > 0) unseen_sum += 100.0 * outcome->unseen.right / outcome->unseen.objects();
    result.scenarios.push_back(std::move(*outcome));
  }
  if (!scenarios.empty()) {
    result.mean_scenario_percent = percent_sum / static_cast<double>(scenarios.size());
    result.mean_unseen_percent = unseen_sum / static_cast<double>(scenarios.size());
  }
  if (advisor) {
    LlmTotals totals = advisor->totals();
    result.llm_calls = totals.calls;
    result.llm_failures = totals.failures;
  }
  result.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace

std::vector<CurvePoint> calibration_curve(const SettingResult& result) {
  std::vector<CurvePoint> curve;
  for (double threshold : {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.98, 0.99}) {
    CurvePoint point{threshold, 0, 0, 0};
    for (const ScenarioOutcome& s : result.scenarios)
      for (const ObjectOutcome& o : s.objects) {
        if (result.setting.protocol == Protocol::kExamples && !o.unseen) continue;
        if (o.proposed.empty() || o.belief < threshold) ++point.asked;
        else if (o.proposed == o.wanted) ++point.right;
        else ++point.wrong;
      }
    curve.push_back(point);
  }
  return curve;
}

std::vector<RecordedScore> score_recorded_answers(const std::vector<TidyBotScenario>& scenarios,
                                                  const std::vector<llm::RecordedAnswer>& answers) {
  std::vector<RecordedScore> scores;
  for (const char* method : {"summarization", "human-summary", "examples-only", "commonsense"}) {
    RecordedScore score;
    score.method = method;
    double sum = 0;
    std::map<std::string, std::pair<double, int>> tags;  // sum, count
    for (const TidyBotScenario& scenario : scenarios) {
      const std::set<std::string> unseen(scenario.unseen_objects.begin(), scenario.unseen_objects.end());
      auto answer = std::find_if(answers.begin(), answers.end(), [&](const llm::RecordedAnswer& a) {
        return a.scenario == scenario.index && a.method == score.method && a.step == "placement" &&
               std::set<std::string>(a.objects.begin(), a.objects.end()) == unseen;
      });
      if (answer == answers.end() || unseen.empty()) continue;
      int right = 0;
      for (const std::string& object : scenario.unseen_objects) {
        auto placed = std::find_if(answer->placements.begin(), answer->placements.end(),
                                   [&](const auto& p) { return p.first == object; });
        if (placed != answer->placements.end() && placed->second == scenario.destination(object)) ++right;
      }
      const double percent = 100.0 * right / static_cast<double>(unseen.size());
      sum += percent;
      ++score.scenarios;
      for (const std::string& tag : scenario.tags) {
        tags[tag].first += percent;
        ++tags[tag].second;
      }
    }
    if (score.scenarios == 0) continue;
    score.mean_percent = sum / score.scenarios;
    for (const auto& [tag, total] : tags) score.by_tag[tag] = total.first / total.second;
    scores.push_back(std::move(score));
  }
  return scores;
}

Result<BenchmarkResults> run_tidybot(const std::vector<TidyBotScenario>& scenarios, const BenchmarkOptions& options) {
  Bench bench{options, language::Lexicon::open_default(), {}};
  BenchmarkResults results;
  results.recorded = score_recorded_answers(scenarios, options.recorded_answers);
  std::vector<Setting> settings = options.settings;
  if (settings.empty()) {
    for (const Setting& setting : all_settings()) {
      if (setting.llm && !options.llm) results.skipped.push_back(setting.name);
      else settings.push_back(setting);
    }
  }
  for (const Setting& setting : settings) {
    auto result = run_setting(bench, scenarios, setting);
    if (!result) return tl::unexpected(result.error());
    results.results.push_back(std::move(*result));
  }
  return results;
}

}  // namespace apprentice::benchmark
