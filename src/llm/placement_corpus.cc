#include "llm/placement_corpus.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "llm/preference_prompts.h"
#include "util/file.h"
#include "util/text.h"

namespace apprentice::llm {

namespace {

using nlohmann::json;

std::set<std::string> keys_of(const std::vector<std::string>& names, NameOf of) {
  std::set<std::string> out;
  for (const std::string& name : names) out.insert(name_key(name, of));
  return out;
}

std::set<std::pair<std::string, std::string>> pair_keys(const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::set<std::pair<std::string, std::string>> out;
  for (const auto& [thing, place] : pairs) out.emplace(name_key(thing), name_key(place, NameOf::kPlace));
  return out;
}

// A rule compared as said: lower case, spaces collapsed, no final period.
std::string rule_key(std::string_view rule) {
  std::string text = to_lower(join(split_words(rule), " "));
  while (!text.empty() && (text.back() == '.' || text.back() == ' ')) text.pop_back();
  return text;
}

std::vector<std::string> strings(const json& value) {
  std::vector<std::string> out;
  for (const json& item : value) out.push_back(item.get<std::string>());
  return out;
}

std::vector<std::pair<std::string, std::string>> pairs(const json& value) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const json& pair : value) {
    if (!pair.is_array() || pair.size() != 2) throw std::runtime_error("expected [object, receptacle] pairs");
    out.emplace_back(pair[0].get<std::string>(), pair[1].get<std::string>());
  }
  return out;
}

std::vector<TokenLogprob> word_tokens(std::string_view text) {
  std::vector<TokenLogprob> tokens;
  for (const std::string& word : split_words(text))
    tokens.push_back(TokenLogprob{tokens.empty() ? word : " " + word, std::numeric_limits<double>::quiet_NaN()});
  return tokens;
}

}  // namespace

bool PlacementCorpusClient::recognizes(const std::filesystem::path& path) {
  auto lines = read_input_lines(path);
  if (!lines) return false;
  for (const std::string& line : *lines) {
    if (trim(line).empty()) continue;
    json record = json::parse(line, nullptr, false);
    return record.is_object() && record.contains("method") && record.contains("step");
  }
  return false;
}

Result<std::vector<RecordedAnswer>> read_recorded_answers(const std::filesystem::path& path) {
  auto lines = read_input_lines(path);
  if (!lines) return tl::unexpected(prefix_error(lines.error(), "the placement corpus"));
  std::vector<RecordedAnswer> answers;
  std::size_t number = 0;
  for (const std::string& line : *lines) {
    ++number;
    if (trim(line).empty()) continue;
    try {
      json record = json::parse(line);
      if (!record.is_object()) throw std::runtime_error("not a JSON object");
      RecordedAnswer answer;
      if (auto scenario = record.find("scenario"); scenario != record.end() && scenario->is_number_integer())
        answer.scenario = scenario->get<int>();
      answer.method = record.at("method").get<std::string>();
      answer.step = record.at("step").get<std::string>();
      answer.receptacles = strings(record.at("receptacles"));
      if (answer.step != "summary" && answer.step != "placement")
        throw std::runtime_error("step is neither summary nor placement");
      if (answer.method != "summarization" && answer.method != "human-summary" && answer.method != "examples-only" &&
          answer.method != "commonsense")
        throw std::runtime_error("unknown method " + apprentice::quoted(answer.method));
      const bool by_rule = answer.method == "summarization" || answer.method == "human-summary";
      if (answer.step == "summary" || answer.method == "examples-only") answer.examples = pairs(record.at("examples"));
      if (answer.step == "summary" || by_rule) answer.summary = std::string(trim(record.at("summary").get<std::string>()));
      if (answer.step == "placement") {
        answer.objects = strings(record.at("objects"));
        answer.placements = pairs(record.at("placements"));
      }
      answers.push_back(std::move(answer));
    } catch (const std::exception& e) {
      return make_error(ErrorCode::kDataLoss,
                        path.string() + ":" + std::to_string(number) + ": not a placement corpus line: " + e.what());
    }
  }
  return answers;
}

Result<std::unique_ptr<PlacementCorpusClient>> PlacementCorpusClient::open(const std::filesystem::path& path) {
  auto answers = read_recorded_answers(path);
  if (!answers) return tl::unexpected(answers.error());
  std::vector<Summary> summaries;
  std::vector<Placements> placements;
  for (const RecordedAnswer& answer : *answers) {
    const Keys receptacles = keys_of(answer.receptacles, NameOf::kPlace);
    if (answer.step == "summary") {
      summaries.push_back(Summary{receptacles, pair_keys(answer.examples), answer.summary});
      continue;
    }
    Placements entry;
    entry.receptacles = receptacles;
    if (answer.method == "summarization" || answer.method == "human-summary") {
      entry.knowledge = Placements::Knowledge::kRule;
      entry.rule = rule_key(answer.summary);
    } else if (answer.method == "examples-only") {
      entry.knowledge = Placements::Knowledge::kExamples;
      entry.examples = pair_keys(answer.examples);
    }
    entry.objects = keys_of(answer.objects, NameOf::kThing);
    for (const auto& [thing, place] : answer.placements) {
      const std::string key = name_key(thing);
      auto placed = [&](const auto& p) { return p.first == key; };
      if (std::none_of(entry.placed.begin(), entry.placed.end(), placed)) entry.placed.emplace_back(key, place);
    }
    placements.push_back(std::move(entry));
  }
  return std::unique_ptr<PlacementCorpusClient>(
      new PlacementCorpusClient(path, std::move(summaries), std::move(placements)));
}

std::string PlacementCorpusClient::describe() const {
  return "corpus " + path_.string() + " (recorded summaries and placements)";
}

std::string PlacementCorpusClient::summary_for(const QueryAbout& about) const {
  const Keys receptacles = keys_of(about.receptacles, NameOf::kPlace);
  const PairKeys examples = pair_keys(about.examples);
  for (const Summary& s : summaries_)
    if (s.receptacles == receptacles && s.examples == examples) return s.summary;
  return {};
}

std::string PlacementCorpusClient::placements_for(const QueryAbout& about) const {
  const Keys receptacles = keys_of(about.receptacles, NameOf::kPlace);
  const std::string rule = rule_key(about.summary);
  const PairKeys examples = pair_keys(about.examples);
  const Keys objects = keys_of(about.objects, NameOf::kThing);
  std::vector<const Placements*> matching;
  for (const Placements& p : placements_) {
    if (p.receptacles != receptacles) continue;
    const bool same = !rule.empty() ? p.knowledge == Placements::Knowledge::kRule && p.rule == rule
                      : !examples.empty() ? p.knowledge == Placements::Knowledge::kExamples && p.examples == examples
                                          : p.knowledge == Placements::Knowledge::kNone;
    if (same) matching.push_back(&p);
  }
  auto overlap = [&](const Placements* p) {
    return std::count_if(objects.begin(), objects.end(), [&](const std::string& o) { return p->objects.contains(o); });
  };
  std::stable_sort(matching.begin(), matching.end(),
                   [&](const Placements* a, const Placements* b) { return overlap(a) > overlap(b); });
  std::string out;
  for (const std::string& object : about.objects) {
    const std::string key = name_key(object);
    for (const Placements* p : matching) {
      auto found = std::find_if(p->placed.begin(), p->placed.end(), [&](const auto& e) { return e.first == key; });
      if (found == p->placed.end()) continue;
      out += (out.empty() ? "" : "\n") + object + " -> " + found->second;
      break;
    }
  }
  return out;
}

Result<Completion> PlacementCorpusClient::do_complete(const CompletionRequest& request) {
  Completion completion;
  completion.source = ResponseSource::kCorpus;
  completion.finish_reason = "stop";
  completion.prompt_tokens = static_cast<int64_t>(split_words(request.prompt).size());
  const QueryAbout& about = request.about;
  if (about.kind == QueryKind::kSummary) completion.text = summary_for(about);
  else if (about.kind == QueryKind::kPlacement) completion.text = placements_for(about);
  completion.answered = !completion.text.empty();
  completion.tokens = word_tokens(completion.text);
  completion.completion_tokens = static_cast<int64_t>(completion.tokens.size());
  return completion;
}

}  // namespace apprentice::llm
