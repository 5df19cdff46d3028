// The benchmark's table and JSON (tidybot_benchmark.h).
#include <cstdio>
#include <set>

#include <nlohmann/json.hpp>

#include "benchmark/tidybot_benchmark.h"
#include "util/json.h"

namespace apprentice::benchmark {

namespace {

std::string row_text(const char* format, auto... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

double percent(int part, int whole) { return whole == 0 ? 0.0 : 100.0 * part / whole; }

std::string describe(const Setting& setting) {
  std::string out = setting.protocol == Protocol::kExamples ? "A" : "B";
  out += setting.teacher ? ", teacher" : ", alone";
  if (setting.llm) out += ", LLM";
  return out;
}

nlohmann::json tally_json(const Tally& tally) {
  return {{"objects", tally.objects()}, {"right", tally.right}, {"wrong", tally.wrong}, {"left", tally.left},
          {"questions", tally.questions}, {"instructions", tally.instructions}};
}

}  // namespace

std::string format_tidybot_table(const BenchmarkResults& results) {
  std::string out;
  if (results.results.empty()) return "No setting ran.\n";
  const std::size_t scenarios = results.results.front().scenarios.size();
  out += "TidyBot benchmark: " + std::to_string(scenarios) + " scenarios.\n";
  out += row_text("%-14s %-16s %7s %6s %6s %6s %10s %7s %8s %9s %9s\n", "Setting", "", "Objects", "Right%", "Wrong%",
                  "Left%", "Questions", "Mean%", "Unseen%", "LLM calls", "Wall ms");
  for (const SettingResult& r : results.results) {
    const Tally& t = r.total;
    const double per_scenario = r.scenarios.empty() ? 0.0 : static_cast<double>(t.questions) / r.scenarios.size();
    out += row_text("%-14s %-16s %7d %6.1f %6.1f %6.1f %10.2f %7.1f %8.1f %9d %9.0f\n", r.setting.name.c_str(),
                    describe(r.setting).c_str(), t.objects(), percent(t.right, t.objects()),
                    percent(t.wrong, t.objects()), percent(t.left, t.objects()), per_scenario, r.mean_scenario_percent,
                    r.mean_unseen_percent, r.llm_calls, r.wall_ms);
  }
  out += "A: the seen placements taught, then the unseen objects; B: the person's note, then every object.\n";
  out += "Questions: per scenario, about where things go. Mean%: right, the mean over scenarios (as TidyBot reports);\n"
         "Unseen%: the same of the unseen objects alone, what TidyBot's figures are about.\n";
  out += "TidyBot published (all 96 scenarios, unseen objects, mean over scenarios):";
  bool first = true;
  for (const PublishedFigure& figure : tidybot_published()) {
    out += row_text("%s %s %.1f%%", first ? "" : ",", figure.method, figure.percent);
    first = false;
  }
  out += ".\n";
  std::set<std::string> tags;
  for (const SettingResult& r : results.results)
    for (const auto& [tag, tally] : r.by_tag) tags.insert(tag);
  out += "\nRight% by tag (a scenario counts under each of its tags)\n";
  out += row_text("%-20s", "Tag");
  for (const SettingResult& r : results.results) out += row_text(" %13s", r.setting.name.c_str());
  out += "\n";
  for (const std::string& tag : tags) {
    out += row_text("%-20s", tag.c_str());
    for (const SettingResult& r : results.results) {
      auto it = r.by_tag.find(tag);
      const Tally t = it == r.by_tag.end() ? Tally{} : it->second;
      out += row_text(" %6.1f (%4d)", percent(t.right, t.objects()), t.objects());
    }
    out += "\n";
  }
  out += "\nCalibration: acting alone at belief >= t, right / wrong / asked, % of the objects measured\n";
  out += row_text("%-20s", "t");
  for (const SettingResult& r : results.results) out += row_text(" %19s", r.setting.name.c_str());
  out += "\n";
  std::vector<std::vector<CurvePoint>> curves;
  for (const SettingResult& r : results.results) curves.push_back(calibration_curve(r));
  for (std::size_t i = 0; !curves.empty() && i < curves.front().size(); ++i) {
    out += row_text("%-20.2f", curves.front()[i].threshold);
    for (const auto& curve : curves) {
      const CurvePoint& p = curve[i];
      const int n = p.right + p.wrong + p.asked;
      out += row_text("  %5.1f %5.1f %5.1f", percent(p.right, n), percent(p.wrong, n), percent(p.asked, n));
    }
    out += "\n";
  }
  if (!results.recorded.empty()) {
    out += "\nTidyBot's recorded answers on these scenarios (unseen objects, mean over scenarios), by tag\n";
    out += row_text("%-20s", "Tag");
    for (const RecordedScore& r : results.recorded) out += row_text(" %13s", r.method.c_str());
    out += "\n";
    out += row_text("%-20s", "all");
    for (const RecordedScore& r : results.recorded) out += row_text(" %13.1f", r.mean_percent);
    out += "\n";
    for (const std::string& tag : tags) {
      out += row_text("%-20s", tag.c_str());
      for (const RecordedScore& r : results.recorded) {
        auto it = r.by_tag.find(tag);
        out += it == r.by_tag.end() ? row_text(" %13s", "--") : row_text(" %13.1f", it->second);
      }
      out += "\n";
    }
  }
  if (!results.skipped.empty()) {
    std::string names;
    for (const std::string& name : results.skipped) names += (names.empty() ? "" : ", ") + name;
    out += "\nSkipped for want of an LLM: " + names + " (pass --llm SPEC, e.g. --llm corpus:llm-dev.jsonl).\n";
  }
  return out;
}

std::string tidybot_json(const BenchmarkResults& results) {
  nlohmann::json settings = nlohmann::json::array();
  for (const SettingResult& r : results.results) {
    nlohmann::json by_tag = nlohmann::json::object();
    for (const auto& [tag, tally] : r.by_tag) by_tag[tag] = tally_json(tally);
    nlohmann::json scenarios = nlohmann::json::array();
    for (const ScenarioOutcome& s : r.scenarios) {
      nlohmann::json objects = nlohmann::json::array();
      for (const ObjectOutcome& o : s.objects)
        objects.push_back({{"object", o.object}, {"wanted", o.wanted}, {"placed", o.placed}, {"unseen", o.unseen},
                           {"proposed", o.proposed}, {"belief", o.belief}});
      nlohmann::json entry = tally_json(s.tally);
      entry["index"] = s.index;
      entry["tags"] = s.tags;
      entry["placements"] = objects;
      if (!s.transcript.empty()) entry["transcript"] = s.transcript;
      scenarios.push_back(entry);
    }
    nlohmann::json entry = tally_json(r.total);
    entry["setting"] = r.setting.name;
    entry["protocol"] = r.setting.protocol == Protocol::kExamples ? "A" : "B";
    entry["teacher"] = r.setting.teacher;
    entry["llm"] = r.setting.llm;
    entry["mean_scenario_percent"] = r.mean_scenario_percent;
    entry["unseen"] = tally_json(r.unseen);
    entry["mean_unseen_percent"] = r.mean_unseen_percent;
    entry["llm_calls"] = r.llm_calls;
    entry["llm_failures"] = r.llm_failures;
    entry["wall_ms"] = r.wall_ms;
    entry["by_tag"] = by_tag;
    nlohmann::json curve = nlohmann::json::array();
    for (const CurvePoint& p : calibration_curve(r))
      curve.push_back({{"threshold", p.threshold}, {"right", p.right}, {"wrong", p.wrong}, {"asked", p.asked}});
    entry["calibration"] = curve;
    entry["scenarios"] = scenarios;
    settings.push_back(entry);
  }
  nlohmann::json published = nlohmann::json::array();
  for (const PublishedFigure& figure : tidybot_published())
    published.push_back({{"method", figure.method}, {"percent", figure.percent}});
  nlohmann::json recorded = nlohmann::json::array();
  for (const RecordedScore& r : results.recorded)
    recorded.push_back({{"method", r.method}, {"scenarios", r.scenarios}, {"mean_percent", r.mean_percent},
                        {"by_tag", r.by_tag}});
  return dump_json(nlohmann::json{{"settings", settings},
                                  {"skipped", results.skipped},
                                  {"tidybot_published", published},
                                  {"tidybot_recorded", recorded}},
                   2);
}

}  // namespace apprentice::benchmark
