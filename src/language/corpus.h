// Grounding a corpus of LLM goal statements, such as the 1,747 GPT-3
// responses of ../shared/data/stars-tidy-kitchen/goal_responses.jsonl: one
// JSON object per line with at least `object` (a category) and `response`;
// `start_location`, `subtask` say where the object was; `stars_viable` (and
// `mismatch_type`), when present, are another agent's verdicts to compare
// with. `apprentice interpret --corpus` prints the report.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "language/grounding.h"
#include "util/result.h"
#include "world/scenario.h"

namespace apprentice::language {

struct CorpusLine {
  std::size_t line_number = 0;  // 1-based, in the file
  std::string object;           // category: "plastic-bottle"
  std::string start_location;   // "table", "counter", "dish rack"; may be empty
  std::string subtask;          // "clear"; may be empty
  std::string response;         // the LLM's words
  std::optional<bool> label_viable;       // stars_viable
  std::optional<std::string> label_kind;  // mismatch_type
};

// Reads JSON lines; blank lines are skipped. A line that is not a JSON
// object with string `object` and `response` is an kInvalidInput error
// naming the line.
Result<std::vector<CorpusLine>> read_corpus(const std::filesystem::path& path);

// The object a line is about: the first object (in id order) of its
// category at its start location, else at its subtask's place, else
// anywhere; nullopt if the world has none.
std::optional<ObjectId> object_for_line(const Scenario& scenario, const CorpusLine& line);

struct CorpusResult {
  const CorpusLine* line = nullptr;
  std::optional<ObjectId> object;
  Interpretation interpretation;
};

// "goal", "action", "task", or a failure kind: "unknown-word", ...
std::string outcome_name(const Interpretation& interpretation);

struct CorpusReport {
  std::size_t lines = 0;
  std::map<std::string, std::size_t> outcomes;  // by outcome_name
  std::size_t labelled = 0;                     // lines with stars_viable
  std::size_t both_viable = 0, both_not = 0, ours_only = 0, theirs_only = 0;
  // (their mismatch_type or "viable") -> our outcome -> count
  std::map<std::string, std::map<std::string, std::size_t>> confusion;
  std::size_t through_wordnet = 0;  // lines where some phrase was grounded through WordNet
  std::size_t without_object = 0;   // lines whose category the world lacks
};

// Grounds every line's response as a goal for its object.
std::vector<CorpusResult> ground_corpus(const Grounder& grounder, const Scenario& scenario,
                                        std::span<const CorpusLine> lines);
CorpusReport summarize(std::span<const CorpusResult> results);

// A plain-text table, and the same as one JSON object.
std::string format_report(const CorpusReport& report);
std::string format_report_json(const CorpusReport& report);

}  // namespace apprentice::language
