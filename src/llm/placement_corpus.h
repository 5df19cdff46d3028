// Answers a person's-preference queries (llm/preference_prompts.h: a
// summary of placements, placements by a rule, by examples or by common
// sense) from recorded answers, by content: the TidyBot benchmark's cache
// of text-davinci-003 answers (../shared/data/tidybot-benchmark/
// llm-dev.jsonl; its README gives the keys). No model runs; every answer
// says source = kCorpus, and carries no log-probabilities (the cache kept
// none).
//
// Matching, names compared by name_key (so "Rubik's cube" is "rubiks
// cube", and "pillow 2" a pillow):
//  - a summary query is answered by the summary recorded for the same
//    places and the same examples (as sets);
//  - a placement query by the placements recorded for the same places and
//    the same knowledge: the same rule (method summarization or
//    human-summary, the rule compared in lower case without its final
//    period), the same examples (examples-only), or neither (commonsense).
//    Each thing asked about gets its place from the recorded answer that
//    placed it, among those that share the most things with the query (a
//    record's things are one scenario's seen or unseen objects); a thing
//    no record placed is left out of the answer.
// The answer is written in our prompt's own form, one "thing -> place"
// line per thing, in the query's words for the thing and the record's for
// the place. Queries of other kinds, and those no record matches, are
// answered "nothing" (answered = false), as the goal corpus does.
#pragma once

#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

// One recorded answer as the file holds it (the README of the TidyBot
// corpus gives the keys); for scoring the recorded answers themselves.
struct RecordedAnswer {
  int scenario = 0;    // the benchmark's index, for reference
  std::string method;  // summarization, human-summary, examples-only, commonsense
  std::string step;    // summary, placement
  std::vector<std::string> receptacles;
  std::vector<std::pair<std::string, std::string>> examples;  // summary; examples-only placement
  std::string summary;                                        // summary step; rule-based placements
  std::vector<std::string> objects;                           // placement
  std::vector<std::pair<std::string, std::string>> placements;  // placement, as parsed by the benchmark
};

// Every record of such a file. Errors: kNotFound, kIo, kDataLoss (a line
// that is not such a record, naming the line).
Result<std::vector<RecordedAnswer>> read_recorded_answers(const std::filesystem::path& path);

class PlacementCorpusClient : public LlmClient {
 public:
  // Whether the file's first line is such a record (keys method and step),
  // so that corpus:FILE can tell it from a goal corpus. False for a file
  // that cannot be read (opening it then says why).
  static bool recognizes(const std::filesystem::path& path);
  // Errors: kNotFound (no file), kDataLoss (a line that is not such a
  // record, naming the line), kIo.
  static Result<std::unique_ptr<PlacementCorpusClient>> open(const std::filesystem::path& path);

  std::string describe() const override;
  std::size_t size() const { return summaries_.size() + placements_.size(); }

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  using Keys = std::set<std::string>;
  using PairKeys = std::set<std::pair<std::string, std::string>>;
  struct Summary {
    Keys receptacles;
    PairKeys examples;
    std::string summary;  // verbatim
  };
  struct Placements {
    enum class Knowledge { kRule, kExamples, kNone } knowledge = Knowledge::kNone;
    Keys receptacles;
    std::string rule;  // kRule: the summary, normalized
    PairKeys examples;  // kExamples
    Keys objects;
    std::vector<std::pair<std::string, std::string>> placed;  // (thing key, place as recorded)
  };
  PlacementCorpusClient(std::filesystem::path path, std::vector<Summary> summaries, std::vector<Placements> placements)
      : path_(std::move(path)), summaries_(std::move(summaries)), placements_(std::move(placements)) {}

  std::string summary_for(const QueryAbout& about) const;
  std::string placements_for(const QueryAbout& about) const;

  std::filesystem::path path_;
  std::vector<Summary> summaries_;
  std::vector<Placements> placements_;
};

}  // namespace apprentice::llm
