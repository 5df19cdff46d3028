// What the LLM says of a person's preferences in one session (issue 20):
// its summary of the placements taught, read as a person's rule is
// (language/rule_reader.h), and where it would put each thing still to
// place, by that summary, by the person's own rule when one was said, by
// the examples, or by common sense. Asked once per session, for every thing
// at the places being cleared, the way TidyBot asks: one summary, one
// placement query. What the agent does with it (act, ask, weigh it against
// its other sources) is its decision's.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "agent/llm_advisor.h"
#include "knowledge/goal_memory.h"
#include "language/lexicon.h"
#include "language/rule_reader.h"
#include "world/world.h"

namespace apprentice {

class LlmPreferences {
 public:
  // Asks the LLM, the first time only. `taught`: the goals learned for the
  // task being done (their placements are the examples); `things`: the
  // things to place; `away_from`: the places they are cleared from (not
  // destinations); `person_rule`: what the person said as a rule ("" if
  // nothing), which is placed by instead of a summary. `learned_as` gives
  // the kinds the session renamed for this world (agent/transfer.h) as they
  // were taught: the examples are what the person showed.
  void consult(LlmAdvisor& llm, const World& world, const std::vector<GoalKnowledge>& taught,
               const std::map<std::string, std::string>& learned_as, const std::vector<ObjectId>& things,
               const std::vector<ObjectId>& away_from, const std::string& person_rule,
               const language::Lexicon& lexicon);
  bool consulted() const { return consulted_; }

  // The place the LLM gave `thing`, if it placed it.
  std::optional<ObjectId> place_for(ObjectId thing) const;
  // Where the LLM put `thing` from the examples alone, asked beside the
  // placement by its summary (TidyBot's "examples only"); a second opinion
  // that does not go through the summary's words.
  std::optional<ObjectId> place_by_examples(ObjectId thing) const;
  // Whether the LLM's summary, given back to it, puts every example where
  // it was taught; nullopt when no summary was checked. A summary that
  // loses an example is a lossy account of the person.
  std::optional<bool> summary_keeps_examples() const { return summary_keeps_examples_; }
  // Its summary of the examples ("" if none was asked or it gave none), and
  // that summary as the rule reader reads it.
  const std::string& summary() const { return summary_; }
  const std::optional<language::RuleReading>& summary_rule() const { return summary_rule_; }
  // The rule the placements were asked by: the person's, or the summary;
  // "" when they were asked by the examples or by common sense.
  const std::string& placed_by() const { return placed_by_; }

 private:
  bool consulted_ = false;
  std::string summary_;
  std::optional<language::RuleReading> summary_rule_;
  std::string placed_by_;
  std::map<ObjectId, ObjectId> placements_;
  std::map<ObjectId, ObjectId> by_examples_;
  std::optional<bool> summary_keeps_examples_;
};

// A place as a person names it, without an article: "left storage box".
std::string place_words(const World& world, ObjectId place);

}  // namespace apprentice
