// The LLM as a source of a person's preferences (issue 20): it summarizes
// where a person put things as a rule in one sentence, and places new
// things by a rule (the person's own, or its summary), by the examples
// alone, or by common sense. The prompts are ours (data/prompts/summary.txt
// and placement.txt); a live model answers them as any query, and the
// corpus backend answers them from recorded answers by content
// (llm/placement_corpus.h). What the answers mean to the agent (a rule to
// read, placements to weigh) is the agent's business.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

// A thing and the place it goes, as the world names them ("rubiks cube",
// "left storage box").
using ThingPlace = std::pair<std::string, std::string>;

class PreferencePrompts {
 public:
  // Reads summary.txt and placement.txt from `dir`. Errors: kNotFound or kIo
  // for a missing or unreadable file; kInvalidInput for a template with an
  // unknown {placeholder} or without the ones it needs.
  static Result<PreferencePrompts> load(const std::filesystem::path& dir);

  // "Summarize this person's rule": stopped at a newline, at temperature 0.
  CompletionRequest summary_request(const std::vector<std::string>& receptacles,
                                    const std::vector<ThingPlace>& examples) const;
  // "Where does each of these go": by `summary` when it is not empty, else
  // by `examples` when there are any, else by common sense.
  CompletionRequest placement_request(const std::vector<std::string>& receptacles, const std::string& summary,
                                      const std::vector<ThingPlace>& examples,
                                      const std::vector<std::string>& objects) const;

 private:
  PreferencePrompts(std::string summary, std::string placement)
      : summary_(std::move(summary)), placement_(std::move(placement)) {}
  std::string summary_;
  std::string placement_;
};

// The rule a summary completion states: its first line that is not empty,
// trimmed, without a leading "Rule:" or "Summary:".
std::string read_summary(std::string_view completion);

// The placements a completion states, one per line: "thing -> place",
// "thing: place", pick_and_place("thing", "place"), "Put the thing in the
// place." Each is matched to one of `objects` and one of `receptacles` by
// name_key (a line whose thing or place matches none is dropped; a thing
// placed twice keeps its first place). In the order of the lines.
std::vector<ThingPlace> read_placements(std::string_view completion, const std::vector<std::string>& objects,
                                        const std::vector<std::string>& receptacles);

// The normal form in which a name is matched, in the world's words or
// another's: lower case, apostrophes dropped, other punctuation and
// hyphens as spaces, spaces collapsed, a leading "the" dropped. A thing's
// name also drops a trailing instance number ("pillow 2" is a pillow); a
// place's keeps it ("bin 1" is not "bin 2").
enum class NameOf { kThing, kPlace };
std::string name_key(std::string_view name, NameOf of = NameOf::kThing);

}  // namespace apprentice::llm
