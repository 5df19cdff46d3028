// Answers goal queries from a corpus of recorded goal statements (JSONL, one
// response per line, as in shared/data/stars-tidy-kitchen/goal_responses.jsonl:
// fields object, response, and optionally start_location, subtask,
// condition, rank). No model runs; every answer says source = kCorpus.
//
// Matching: a goal query is answered from the lines whose object equals the
// query's object_category, and whose subtask and start_location equal the
// query's subtask and place where the query gives them (all compared after
// normalize_label / normalize_place). Action and action-word queries, and goal
// queries with no matching line, are answered "nothing" (answered = false):
// not an error, the agent asks the instructor.
//
// Ranking: by default the matching lines of every condition are pooled and
// identical responses (same words, any case) merged; the most often retrieved
// come first (ties: lower rank field, then earlier line). Each token of a
// response gets log(count / total), so exp(mean log-probability) is the share
// of retrievals that gave that response: a stand-in for the model's
// probability. With a condition set (e.g. "TBP", the paper's own method),
// only that condition's lines are used.
//
// Walking the list: a query at temperature 0 gets the first response; each
// following query for the same (object, subtask, place) at a temperature
// above 0 gets the next one, wrapping round at the end. So retrieve_goals'
// temperature-0 query then its 0.9/1.0 queries see the distinct responses in
// rank order, deterministically.
//
// Usage: prompt and completion tokens are whitespace-separated words.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

class CorpusClient : public LlmClient {
 public:
  // Errors: kNotFound (no file), kDataLoss (a line that is not a JSON object
  // with string fields object and response; the message names the line),
  // kInvalidInput (a condition no line has).
  static Result<std::unique_ptr<CorpusClient>> open(const std::filesystem::path& path,
                                                    std::string condition = "");
  std::string describe() const override;

  struct Answer {
    std::string text;
    int count = 0;  // how many lines gave it
  };
  // The ranked responses for a query about (object, subtask, place); empty
  // strings are wildcards. For tests and reports.
  std::vector<Answer> ranked(std::string_view object, std::string_view subtask,
                             std::string_view place) const;

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  struct Line {
    std::string object;    // normalized
    std::string subtask;   // normalized
    std::string place;     // normalized
    std::string response;  // verbatim
    long rank = 0;
  };
  CorpusClient(std::filesystem::path path, std::string condition, std::vector<Line> lines)
      : path_(std::move(path)), condition_(std::move(condition)), lines_(std::move(lines)) {}

  std::filesystem::path path_;
  std::string condition_;
  std::vector<Line> lines_;  // only the selected condition's
  std::map<std::string, size_t> cursors_;  // next index per (object, subtask, place)
};

}  // namespace apprentice::llm
