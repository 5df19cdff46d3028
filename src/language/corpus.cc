#include "language/corpus.h"

#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "language/reference.h"
#include "util/file.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

// Failure kinds in the order reports list them.
constexpr std::array<std::string_view, 8> kOutcomeOrder = {
    "goal", "action", "task", "unknown-word", "uninterpretable", "ungrounded-object", "affordance-mismatch",
    "unknown-predicate"};

Result<CorpusLine> parse_line(const std::string& text, std::size_t number) {
  auto where = [&](std::string_view what) {
    return make_error(ErrorCode::kInvalidInput, fmt::format("line {}: {}", number, what));
  };
  nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return where("not a JSON object");
  auto string_field = [&](const char* key) -> std::optional<std::string> {
    auto it = j.find(key);
    if (it == j.end() || !it->is_string()) return std::nullopt;
    return it->get<std::string>();
  };
  CorpusLine line;
  line.line_number = number;
  auto object = string_field("object");
  auto response = string_field("response");
  if (!object || !response) return where("expected string fields \"object\" and \"response\"");
  line.object = *object;
  line.response = *response;
  line.start_location = string_field("start_location").value_or("");
  line.subtask = string_field("subtask").value_or("");
  if (auto it = j.find("stars_viable"); it != j.end() && it->is_boolean()) line.label_viable = it->get<bool>();
  line.label_kind = string_field("mismatch_type");
  return line;
}

std::optional<ObjectId> place_named(const Universe& universe, std::string_view name) {
  std::string key = category_key(name);
  for (ObjectId id = 0; id < universe.size(); ++id)
    if (universe.info(id).kind != ObjectKind::kItem && universe.info(id).category == key) return id;
  return std::nullopt;
}

}  // namespace

Result<std::vector<CorpusLine>> read_corpus(const std::filesystem::path& path) {
  auto file = read_input_lines(path);  // within the input limits (util/file.h)
  if (!file) return tl::unexpected(prefix_error(file.error(), "the corpus"));
  std::vector<CorpusLine> lines;
  std::size_t number = 0;
  for (const std::string& text : *file) {
    ++number;
    if (trim(text).empty()) continue;
    auto line = parse_line(text, number);
    if (!line) return tl::unexpected(prefix_error(line.error(), path.string()));
    lines.push_back(std::move(*line));
  }
  return lines;
}

std::optional<ObjectId> object_for_line(const Scenario& scenario, const CorpusLine& line) {
  const World& world = scenario.world;
  const Universe& universe = *world.universe;
  std::vector<ObjectId> candidates = universe.with_category(line.object);
  if (candidates.empty()) return std::nullopt;
  std::optional<ObjectId> place = place_named(universe, line.start_location);
  if (!place && !line.subtask.empty())
    for (const Subtask& s : scenario.task.subtasks)
      if (s.verb == line.subtask) place = s.places.front();
  if (place) {
    for (ObjectId id : candidates) {
      if (world.state.holds(Fact(world.vocabulary.on, {id, *place})) ||
          world.state.holds(Fact(world.vocabulary.in, {id, *place})))
        return id;
    }
  }
  return candidates.front();
}

std::string outcome_name(const Interpretation& interpretation) {
  if (const auto* failure = interpretation.failure()) return std::string(to_string(failure->kind));
  if (std::holds_alternative<Goal>(interpretation.result)) return "goal";
  if (std::holds_alternative<Action>(interpretation.result)) return "action";
  return "task";
}

std::vector<CorpusResult> ground_corpus(const Grounder& grounder, const Scenario& scenario,
                                        std::span<const CorpusLine> lines) {
  std::vector<CorpusResult> results;
  results.reserve(lines.size());
  for (const CorpusLine& line : lines) {
    CorpusResult r;
    r.line = &line;
    r.object = object_for_line(scenario, line);
    r.interpretation = grounder.interpret_goal(line.response, scenario.world, r.object);
    results.push_back(std::move(r));
  }
  return results;
}

CorpusReport summarize(std::span<const CorpusResult> results) {
  CorpusReport report;
  for (const CorpusResult& r : results) {
    ++report.lines;
    std::string outcome = outcome_name(r.interpretation);
    ++report.outcomes[outcome];
    if (!r.object) ++report.without_object;
    for (const Reference& ref : r.interpretation.references) {
      if (ref.method == ReferenceMethod::kWordNet) {
        ++report.through_wordnet;
        break;
      }
    }
    if (!r.line->label_viable) continue;
    ++report.labelled;
    bool ours = outcome == "goal";
    bool theirs = *r.line->label_viable;
    if (ours && theirs) ++report.both_viable;
    if (!ours && !theirs) ++report.both_not;
    if (ours && !theirs) ++report.ours_only;
    if (!ours && theirs) ++report.theirs_only;
    std::string label = theirs ? "viable" : r.line->label_kind.value_or("not viable");
    ++report.confusion[label][outcome];
  }
  return report;
}

std::string format_report(const CorpusReport& report) {
  std::ostringstream out;
  auto pct = [](std::size_t n, std::size_t d) { return d == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(d); };
  out << fmt::format("lines: {}\n\n{:<22}{:>7}{:>9}\n", report.lines, "outcome", "lines", "share");
  for (std::string_view name : kOutcomeOrder) {
    auto it = report.outcomes.find(std::string(name));
    std::size_t n = it == report.outcomes.end() ? 0 : it->second;
    out << fmt::format("{:<22}{:>7}{:>8.1f}%\n", name, n, pct(n, report.lines));
  }
  out << fmt::format("\ngrounded through WordNet: {} lines\n", report.through_wordnet);
  if (report.without_object > 0) out << fmt::format("objects not in the world: {} lines\n", report.without_object);
  if (report.labelled == 0) return out.str();
  out << fmt::format("\nagreement with stars_viable ({} labelled lines): {:.1f}%\n", report.labelled,
                     pct(report.both_viable + report.both_not, report.labelled));
  out << fmt::format("  both viable {}, both not {}, ours only {}, theirs only {}\n", report.both_viable,
                     report.both_not, report.ours_only, report.theirs_only);
  out << "\ntheir verdict -> our outcome\n";
  for (const auto& [label, row] : report.confusion) {
    std::vector<std::string> cells;
    for (const auto& [outcome, n] : row) cells.push_back(fmt::format("{} {}", outcome, n));
    out << fmt::format("  {:<20} {}\n", label, join(cells, ", "));
  }
  return out.str();
}

std::string format_report_json(const CorpusReport& report) {
  nlohmann::ordered_json j;
  j["lines"] = report.lines;
  nlohmann::ordered_json outcomes = nlohmann::ordered_json::object();
  for (std::string_view name : kOutcomeOrder) {
    auto it = report.outcomes.find(std::string(name));
    outcomes[std::string(name)] = it == report.outcomes.end() ? 0 : it->second;
  }
  j["outcomes"] = outcomes;
  j["through_wordnet"] = report.through_wordnet;
  j["without_object"] = report.without_object;
  if (report.labelled > 0) {
    j["agreement"] = {{"labelled", report.labelled},     {"both_viable", report.both_viable},
                      {"both_not", report.both_not},     {"ours_only", report.ours_only},
                      {"theirs_only", report.theirs_only}};
    j["confusion"] = report.confusion;
  }
  // Labels come from the input file; never let a bad byte throw.
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace apprentice::language
