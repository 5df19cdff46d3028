// Answers goal queries from a corpus of recorded goal statements (JSONL, one
// response per line, as in shared/data/stars-tidy-kitchen/goal_responses.jsonl:
// fields object, response, and optionally start_location, subtask,
// condition, rank). No model runs; every answer says source = kCorpus.
//
// Matching: a goal query is answered from the lines whose object equals the
// query's object_category, and whose subtask and start_location equal the
// query's subtask and place where the query gives them (all compared after
// normalize_label / normalize_place). Action and action-word queries, goal
// queries with no matching line, and re-prompts (a query that lists
// rejected answers: nothing was recorded for such a prompt) are answered
// "nothing" (answered = false): not an error, the agent goes on as when a
// model has no answer.
//
// Which lines, and in what order (CorpusSelection):
//  - one condition (a STARS run such as TBP, the paper's own method): its
//    responses in that run's own retrieval order, the `rank` field (ties:
//    the earlier line). Responses that differ only in case or spacing are
//    one response, at its best rank. The corpus holds no probabilities, so
//    the tokens' log-probabilities are unreported (NaN) and the candidates
//    keep this order. This is the default, with the condition TBP when the
//    corpus has it (or the corpus's only condition).
//  - pool = all, an ensemble of every condition: identical responses merged,
//    the most often retrieved first (ties: lower rank, then earlier line);
//    each token gets log(count / total), so exp(mean log-probability) is the
//    share of retrievals that gave the response: a vote over runs made by
//    different methods, which tables label "ensemble".
//
// Walking the list: a query at temperature 0 gets the first response; each
// following query for the same (object, subtask, place) at a temperature
// above 0 gets the next one, wrapping round at the end. So retrieve_goals'
// temperature-0 query then its 0.9/1.0 queries see the distinct responses in
// order, deterministically.
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

struct CorpusSelection {
  // One condition's responses; empty: TBP if the corpus has it, else its
  // only condition (a corpus with several and no TBP must name one).
  std::string condition;
  // Every condition, pooled (an ensemble). Excludes `condition`.
  bool pool_all = false;
};

class CorpusClient : public LlmClient {
 public:
  // Errors: kNotFound (no file), kDataLoss (a line that is not a JSON object
  // with string fields object and response, or whose rank is not an
  // integer; the message names the line), kInvalidInput (a condition no line
  // has, or a corpus of several conditions without TBP and none chosen).
  static Result<std::unique_ptr<CorpusClient>> open(const std::filesystem::path& path,
                                                    CorpusSelection selection = {});
  std::string describe() const override;
  bool pools_sources() const override { return pool_all_; }

  // The condition whose lines are used; empty when pooled.
  const std::string& condition() const { return condition_; }

  struct Answer {
    std::string text;
    int count = 0;  // how many lines gave it
  };
  // The ordered responses for a query about (object, subtask, place); empty
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
  CorpusClient(std::filesystem::path path, std::string condition, bool pool_all, std::vector<Line> lines)
      : path_(std::move(path)), condition_(std::move(condition)), pool_all_(pool_all), lines_(std::move(lines)) {}

  std::filesystem::path path_;
  std::string condition_;
  bool pool_all_ = false;
  std::vector<Line> lines_;  // only the selected condition's
  std::map<std::string, size_t> cursors_;  // next index per (object, subtask, place)
};

}  // namespace apprentice::llm
