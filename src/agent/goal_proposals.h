// Where a thing the agent has no goal for may go, before anyone is asked:
// the proposals of its knowledge sources for the decision
// (knowledge/decision.h), in one world.
//
// The sources, each with its own confidence:
//   - similarity: the thing's likeness to the things taught before the
//     session (knowledge/likeness.h: WordNet's classes and the word
//     vectors), and WordNet's nearest learned kind (agent/transfer.h);
//   - induced rules: the classes the examples taught before the session
//     support, per destination (knowledge/induction.h);
//   - the rules a person said, and those read from an LLM's summary;
//   - the LLM's placement of the thing (given by the caller).
// Only what was known when the world was met serves as examples: goals
// learned in the session are the teacher's answers, not evidence for
// guesses (so the paper's one-shot figures stay as they are).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "knowledge/concepts.h"
#include "knowledge/decision.h"
#include "knowledge/goal_memory.h"
#include "knowledge/induction.h"
#include "knowledge/store_engine.h"
#include "knowledge/likeness.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

// How the agent weighs its sources and when it acts alone. The values are
// calibrated on the TidyBot benchmark's development half
// (docs/benchmarks.md, "Calibration").
DecisionPolicy default_decision_policy();

class GoalProposer {
 public:
  // `concepts` must outlive this object; `prior` are the goals known when
  // the session began, in the world's words. Induced rules whose
  // class_rule_key is in `forgotten` are never proposed (the person said
  // to forget them).
  GoalProposer(const ConceptSource& concepts, std::vector<GoalKnowledge> prior, std::set<std::string> forgotten = {});

  // The proposals of the similarity and induced-rule sources, and of
  // `said` (the person's and the LLM's rules), for a thing of `key`
  // (its task, subtask, kind and kind of place). Proposals for a
  // destination this world cannot place things at are left out.
  std::vector<DestinationProposal> propose(const World& world, const GoalKey& key, ObjectId object,
                                           std::span<const ClassRule> said) const;

  // The examples for a thing of `key`: the prior goals that are
  // placements, of the same task, subtask and kind of place when there are
  // such, else of the same task, else all; never the kind itself.
  std::vector<PlacementExample> examples_for(const GoalKey& key) const;
  // The rules induced from those examples (computed once per scope).
  const std::vector<ClassRule>& induced_for(const GoalKey& key) const;

  // Never proposes `rule` (by class_rule_key) again.
  void forget(const ClassRule& rule);

  // Every rule induced from the prior goals, scope by scope, for
  // `knowledge` and reports.
  std::vector<ClassRule> all_induced() const;

 private:
  std::vector<const GoalKnowledge*> prior_for(const GoalKey& key) const;

  const ConceptSource* concepts_;
  std::vector<GoalKnowledge> prior_;
  std::set<std::string> forgotten_;
  mutable std::map<std::string, std::vector<ClassRule>> induced_;  // by scope
};

// The goal a destination gives `object` here (in it or on it, and what the
// destination says of the place's doors); nullopt when the world lacks the
// place or has several that fit it.
std::optional<Goal> goal_at(const World& world, const Destination& destination, ObjectId object);

// Whether the rule a proposal came from says a word that the world gives
// things as a property ("dirty clothes", where the socks are dirty) and
// `object` lacks it, in its properties and its name: such a rule does not
// fit it (the clean t-shirt is no dirty clothes).
bool lacks_a_property_said(const World& world, ObjectId object, const DestinationProposal& proposal);

// How many places here a thing could be put: every surface and receptacle
// but `away_from` (the places being cleared).
std::size_t place_count(const World& world, std::span<const ObjectId> away_from);

// The evidence of a decision, as the agent says it after the destination:
// "like the banana and the apple", "with fruits, as you said" (the
// classes of the person's rules), "as the language model suggests", "as in all 9 other households
// I know of". "" when there is none.
std::string evidence_phrase(const World& world, std::span<const DestinationProposal> support);
// Where a fleet proposal (ProposalSource::kFleet) comes from: "in the one
// other household I know of", "in all 9 other households I know of", "in
// most households I know of (3 of 4)", "in 2 of the 5 other households I
// know of".
std::string fleet_phrase(const DestinationProposal& fleet);

// What a rule is about, in English: "edible fruit", "plastic things",
// "other clothes", "everything else".
std::string rule_subject(const ClassRule& rule);

// A class rule in English, with its evidence and source: "edible fruit
// goes on the coffee table, from the banana and the apple (induced from the
// examples, 83% sure)"; "other clothes go on the bed, as said: \"...\"".
std::string say_class_rule(const ClassRule& rule);

// What the agent generalizes from the goals in `knowledge`, one English
// line per induced rule, scope by scope (the rules are induced anew from
// the goals, so forgetting a goal changes them): what `apprentice
// knowledge` shows.
std::vector<std::string> explain_preferences(const Knowledge& knowledge, const ConceptSource& concepts);

}  // namespace apprentice
