#include "llm/corpus_client.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "util/file.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;

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

}  // namespace

Result<std::unique_ptr<CorpusClient>> CorpusClient::open(const std::filesystem::path& path,
                                                         std::string condition) {
  auto file = read_input_lines(path);  // within the input limits (util/file.h)
  if (!file) return tl::unexpected(prefix_error(file.error(), "the goal corpus"));
  std::vector<Line> lines;
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
      if (!condition.empty() && line_condition != condition) continue;
      Line entry;
      entry.object = normalize_label(line.at("object").get<std::string>());
      entry.response = std::string(trim(line.at("response").get<std::string>()));
      entry.subtask = normalize_label(optional_string(line, "subtask"));
      entry.place = normalize_place(optional_string(line, "start_location"));
      if (auto rank = line.find("rank"); rank != line.end() && rank->is_number_integer()) {
        entry.rank = rank->get<long>();
      }
      if (!entry.response.empty()) lines.push_back(std::move(entry));
    } catch (const std::exception& e) {
      return make_error(ErrorCode::kDataLoss, where + ": not a corpus line: " + e.what());
    }
  }
  if (!condition.empty() && !conditions.contains(condition)) {
    return make_error(ErrorCode::kInvalidInput,
                      "the goal corpus " + path.string() + " has no condition " + apprentice::quoted(condition));
  }
  return std::unique_ptr<CorpusClient>(new CorpusClient(path, std::move(condition), std::move(lines)));
}

std::string CorpusClient::describe() const {
  std::string out = "corpus " + path_.string();
  out += condition_.empty() ? " (all conditions pooled)" : " (condition " + condition_ + ")";
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
    tally.best_rank = std::min(tally.best_rank, line.rank);
  }
  std::sort(tallies.begin(), tallies.end(), [](const Tally& a, const Tally& b) {
    if (a.answer.count != b.answer.count) return a.answer.count > b.answer.count;
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
  if (about.kind == QueryKind::kGoal) {
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

  int total = 0;
  for (const Answer& a : answers) total += a.count;
  const double logprob = std::log(static_cast<double>(answer.count) / total);
  completion.text = answer.text;
  completion.tokens = word_tokens(answer.text, logprob);
  completion.completion_tokens = static_cast<int64_t>(completion.tokens.size());
  completion.finish_reason = "stop";
  return completion;
}

}  // namespace apprentice::llm
