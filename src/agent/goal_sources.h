// Internal to the agent: where the goal of a thing comes from when none is
// known for its kind, in one session. It owns what the sources know and
// what the teacher said of them:
//   - memory and analogy: the agent's knowledge in this world's words
//     (agent/transfer.h);
//   - likeness and the rules the goals induce (agent/goal_proposals.h, over
//     what WordNet and the vectors know of kinds);
//   - the person's rules said, and the LLM's summary of what was taught, as
//     class rules (agent/person_rule.h);
//   - the LLM's placements (agent/llm_preferences.h);
//   - the fleet: what other households of the store chose;
//   - the destinations the teacher refused for a kind, and the goals a
//     "yes" settled for things asked about together.
// It never asks or says anything and never writes the store: the session
// asks the teacher and weighs the proposals (agent_decision.cc). So it can
// be built and tested from a world and knowledge alone.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "agent/llm_preferences.h"
#include "agent/transfer.h"
#include "knowledge/decision.h"
#include "knowledge/preferences.h"
#include "knowledge/store_engine.h"

namespace apprentice {

class GoalSources {
 public:
  // Renames `knowledge` into this world's words (KnowledgeTransfer) and
  // takes the person's rules said in earlier sessions: they hold here too.
  // `lexicon` and `vectors` (may be null) must outlive the sources.
  GoalSources(Knowledge& knowledge, const World& world, const language::Lexicon& lexicon,
              const vectors::WordVectors* vectors);
  GoalSources(const GoalSources&) = delete;
  GoalSources& operator=(const GoalSources&) = delete;

  // Which sources are asked, beside the agent's own knowledge.
  struct Asking {
    const FleetPrior* fleet = nullptr;  // other households' choices; null: not asked
    bool llm = false;                   // the LLM's placements, once consulted
  };
  // Every source's proposals for `object`, whose goal key is `key`, without
  // the destinations the teacher refused for its kind.
  std::vector<DestinationProposal> proposals_for(const World& world, const GoalKey& key, ObjectId object,
                                                 Asking asking) const;
  // The LLM's placements of `object` as proposals: by its summary or the
  // person's rule (kLlmPlacement, surer when its summary puts the examples
  // back where they were taught), and by the examples alone (kLlmExamples);
  // none when it did not place it.
  std::vector<DestinationProposal> llm_placements(const World& world, ObjectId object) const;

  // Asks the LLM, the first time only, for the summary of what was taught
  // (`taught`) and where each of `things` goes; the summary's rules join the
  // said rules (RuleSource::kLlm) in `scope`. Nothing when the LLM has no
  // preference prompts or is not being asked.
  void consult_llm(LlmAdvisor& llm, const World& world, const std::vector<GoalKnowledge>& taught,
                   const std::vector<ObjectId>& things, const std::vector<ObjectId>& away_from, const GoalScope& scope,
                   const language::Lexicon& lexicon);
  bool llm_consulted() const { return llm_preferences_.consulted(); }
  // Whether the LLM placed things by the person's own rule: the agent's
  // reading of the same words is then no independent expert.
  bool llm_placed_by_persons_rule() const { return !rules_said_.empty() && !llm_preferences_.placed_by().empty(); }

  // A person's rule said in this session, as said, and its class rules.
  void hear(std::string said) { rules_said_.push_back(std::move(said)); }
  void add_rule(ClassRule rule) { said_rules_.add(std::move(rule)); }
  void remove_rule(const ClassRule& rule) { said_rules_.remove(rule); }
  const ClassRules& said_rules() const { return said_rules_; }
  // "forget toys": the rule is not proposed again this session.
  void forget_rule(const ClassRule& rule);
  // The rules in use that a person may name to forget: the person's, and
  // those the goals induce.
  std::vector<ClassRule> rules_in_use() const;

  // The teacher said no to `destination` for things of `kind`.
  void refuse(std::string kind, Destination destination) {
    refused_.emplace_back(std::move(kind), std::move(destination));
  }
  // A "yes" asked with another thing settled `goal` for `object`, with
  // what the teacher said.
  void settle(ObjectId object, Goal goal, std::string said) {
    settled_.emplace(object, std::make_pair(std::move(goal), std::move(said)));
  }
  bool settled(ObjectId object) const { return settled_.contains(object); }
  // The goal settled for `object` and the words, once; nullopt if none.
  std::optional<std::pair<Goal, std::string>> take_settled(ObjectId object);

  const KnowledgeTransfer& transfer() const { return transfer_; }
  const LexicalConcepts& concepts() const { return concepts_; }

 private:
  // Constructed in this order: the proposer uses the transfer's renamed
  // goals and the concepts.
  KnowledgeTransfer transfer_;
  LexicalConcepts concepts_;
  GoalProposer proposer_;
  std::vector<std::string> rules_said_;
  ClassRules said_rules_;
  LlmPreferences llm_preferences_;
  std::vector<std::pair<std::string, Destination>> refused_;
  std::map<ObjectId, std::pair<Goal, std::string>> settled_;
};

}  // namespace apprentice
