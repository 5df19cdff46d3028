#include "llm/corpus_client.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <nlohmann/json.hpp>

#include "llm/json_fields.h"
#include "util/file.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;

// The condition a corpus is read as when none is named: the paper's own
// method, template-based prompting, as the STARS runs call it.
constexpr std::string_view kDefaultCondition = "TBP";

// Responses that differ only in case or spacing are the same response.
std::string response_key(std::string_view response) { return to_lower(join(split_words(response), " ")); }

std::string optional_string(const json& line, const char* key) {
  auto it = line.find(key);
  return it != line.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// GPT-style tokens: "the", " goal", " is", ...
std::vector<TokenLogprob> word_tokens(std::string_view text, double logprob) {
  std::vector<TokenLogprob> tokens;
  for (const std::string& word : split_words(text)) {
    tokens.push_back(TokenLogprob{tokens.empty() ? word : " " + word, logprob});
  }
  return tokens;
}

std::string list_conditions(const std::set<std::string>& conditions) {
  std::string out;
  for (const std::string& condition : conditions) out += (out.empty() ? "" : ", ") + condition;
  return out;
}

}  // namespace

Result<std::unique_ptr<CorpusClient>> CorpusClient::open(const std::filesystem::path& path,
                                                         CorpusSelection selection) {
  auto file = read_input_lines(path);  // within the input limits (util/file.h)
  if (!file) return tl::unexpected(prefix_error(file.error(), "the goal corpus"));
  std::vector<std::pair<std::string, Line>> all;  // (condition, line)
  std::set<std::string> conditions;
  size_t number = 0;
  for (const std::string& text : *file) {
    ++number;
    if (trim(text).empty()) continue;
    const std::string where = path.string() + ":" + std::to_string(number);
    try {
      json line = json::parse(text);
      if (!line.is_object()) throw std::runtime_error("not a JSON object");
      std::string line_condition = optional_string(line, "condition");
      conditions.insert(line_condition);
      Line entry;
      entry.object = normalize_label(line.at("object").get<std::string>());
      entry.response = std::string(trim(line.at("response").get<std::string>()));
      entry.subtask = normalize_label(optional_string(line, "subtask"));
      entry.place = normalize_place(optional_string(line, "start_location"));
      if (auto rank = line.find("rank"); rank != line.end()) {
        auto value = json_fields::integer_in(*rank, 0, std::numeric_limits<long>::max());
        if (!value) throw std::runtime_error("rank is not a whole number from 0");
        entry.rank = static_cast<long>(*value);
      }
      if (!entry.response.empty()) all.emplace_back(std::move(line_condition), std::move(entry));
    } catch (const std::exception& e) {
      // nlohmann's exceptions (parse_error, out_of_range for 1e400,
      // type_error) all derive from std::exception.
      return make_error(ErrorCode::kDataLoss, where + ": not a corpus line: " + e.what());
    }
  }
  std::string condition = selection.condition;
  if (selection.pool_all) {
    if (!condition.empty())
      return make_error(ErrorCode::kInvalidInput, "corpus: choose condition=NAME or pool=all, not both");
  } else if (condition.empty()) {
    if (conditions.contains(std::string(kDefaultCondition))) {
      condition = kDefaultCondition;
    } else if (conditions.size() == 1) {
      condition = *conditions.begin();
    } else if (!conditions.empty()) {
      return make_error(ErrorCode::kInvalidInput,
                        "the goal corpus " + path.string() + " holds several conditions (" +
                            list_conditions(conditions) + "): choose one with ,condition=NAME or pool them with ,pool=all");
    }
  } else if (!conditions.contains(condition)) {
    return make_error(ErrorCode::kInvalidInput, "the goal corpus " + path.string() + " has no condition " +
                                                    apprentice::quoted(condition) + " (it has " +
                                                    list_conditions(conditions) + ")");
  }
  std::vector<Line> lines;
  for (auto& [line_condition, line] : all)
    if (selection.pool_all || line_condition == condition) lines.push_back(std::move(line));
  return std::unique_ptr<CorpusClient>(
      new CorpusClient(path, selection.pool_all ? std::string() : condition, selection.pool_all, std::move(lines)));
}

std::string CorpusClient::describe() const {
  std::string out = "corpus " + path_.string();
  out += pool_all_ ? " (ensemble: all conditions pooled)" : " (condition " + condition_ + ")";
  return out;
}

std::vector<CorpusClient::Answer> CorpusClient::ranked(std::string_view object,
                                                       std::string_view subtask,
                                                       std::string_view place) const {
  const std::string want_object = normalize_label(object);
  const std::string want_subtask = normalize_label(subtask);
  const std::string want_place = normalize_place(place);
  struct Tally {
    Answer answer;
    long best_rank;
    size_t first_line;
  };
  std::vector<Tally> tallies;
  std::map<std::string, size_t> index;  // response_key -> tallies index
  for (size_t i = 0; i < lines_.size(); ++i) {
    const Line& line = lines_[i];
    if (want_object.empty() || line.object != want_object) continue;
    if (!want_subtask.empty() && line.subtask != want_subtask) continue;
    if (!want_place.empty() && line.place != want_place) continue;
    auto [it, added] = index.emplace(response_key(line.response), tallies.size());
    if (added) tallies.push_back(Tally{Answer{line.response, 0}, line.rank, i});
    Tally& tally = tallies[it->second];
    ++tally.answer.count;
    if (line.rank < tally.best_rank) {
      tally.best_rank = line.rank;
      tally.answer.text = line.response;  // as it was worded at its best rank
    }
  }
  const bool pooled = pool_all_;
  std::sort(tallies.begin(), tallies.end(), [pooled](const Tally& a, const Tally& b) {
    if (pooled && a.answer.count != b.answer.count) return a.answer.count > b.answer.count;
    if (a.best_rank != b.best_rank) return a.best_rank < b.best_rank;
    return a.first_line < b.first_line;
  });
  std::vector<Answer> answers;
  for (Tally& tally : tallies) answers.push_back(std::move(tally.answer));
  return answers;
}

Result<Completion> CorpusClient::do_complete(const CompletionRequest& request) {
  Completion completion;
  completion.source = ResponseSource::kCorpus;
  completion.prompt_tokens = static_cast<int64_t>(split_words(request.prompt).size());
  const QueryAbout& about = request.about;
  std::vector<Answer> answers;
  if (about.kind == QueryKind::kGoal && about.rejected.empty()) {
    answers = ranked(about.object_category, about.subtask, about.place);
  }
  if (answers.empty()) {
    completion.answered = false;
    completion.finish_reason = "stop";
    return completion;
  }
  const std::string key = normalize_label(about.object_category) + "|" +
                          normalize_label(about.subtask) + "|" + normalize_place(about.place);
  size_t& cursor = cursors_[key];
  size_t pick = 0;
  if (request.temperature > 0.0) pick = cursor;
  cursor = pick + 1;
  const Answer& answer = answers[pick % answers.size()];

  double logprob = std::numeric_limits<double>::quiet_NaN();  // one run's order: no probabilities
  if (pool_all_) {
    int total = 0;
    for (const Answer& a : answers) total += a.count;
    logprob = std::log(static_cast<double>(answer.count) / total);
  }
  completion.text = answer.text;
  completion.tokens = word_tokens(answer.text, logprob);
  completion.completion_tokens = static_cast<int64_t>(completion.tokens.size());
  completion.finish_reason = "stop";
  return completion;
}

}  // namespace apprentice::llm
