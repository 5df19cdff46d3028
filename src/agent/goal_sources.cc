// The sources of a goal for a thing whose kind has none (agent/goal_sources.h).
#include "agent/goal_sources.h"

#include <algorithm>
#include <set>

#include "agent/person_rule.h"
#include "language/generation.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

std::set<std::string> forgotten_keys(const Knowledge& knowledge) {
  std::set<std::string> keys;
  for (const ClassRule& rule : knowledge.forgotten_rules.all()) keys.insert(class_rule_key(rule));
  return keys;
}

// An analogy (agent/transfer.h) as a proposal: the same kind learned in
// another context is memory; a kind near it in WordNet, analogy.
DestinationProposal analogy_proposal(const Analogy& analogy) {
  DestinationProposal proposal;
  proposal.destination = *destination_of(analogy.like.literals);
  proposal.confidence = analogy.confidence;
  proposal.source = analogy.distance == 0 ? ProposalSource::kMemory : ProposalSource::kAnalogy;
  proposal.evidence = {analogy.learned_as};
  proposal.reason = "analogy: like the " + language::spoken_category(analogy.learned_as);
  return proposal;
}

// On the TidyBot benchmark's development half (docs/benchmarks.md, "The
// LLM's placements weighed"): the LLM's placement by its own summary was
// right for 96% of the unseen objects where that summary, given back to
// it, put every example where it was taught, and for 82% where it lost
// one; its placement from the examples alone, for 75%.
constexpr double kLlmPlacementKeepingExamplesConfidence = 0.95;
constexpr double kLlmPlacementLosingExamplesConfidence = 0.85;
constexpr double kLlmByExamplesConfidence = 0.75;

}  // namespace

GoalSources::GoalSources(Knowledge& knowledge, const World& world, const language::Lexicon& lexicon,
                         const vectors::WordVectors* vectors)
    : transfer_(knowledge, world, lexicon),
      concepts_(lexicon, vectors),
      proposer_(concepts_, transfer_.prior_goals(), forgotten_keys(knowledge)) {
  // A person's rules said in earlier sessions hold here too (for the same
  // task, or any task when said before one).
  for (const ClassRule& rule : knowledge.class_rules.all())
    if (rule.source == RuleSource::kPerson) said_rules_.add(rule);
}

std::vector<DestinationProposal> GoalSources::proposals_for(const World& world, const GoalKey& key, ObjectId object,
                                                            Asking asking) const {
  std::vector<DestinationProposal> proposals = proposer_.propose(world, key, object, said_rules_.all());
  if (auto analogy = transfer_.analogy(world, key, object)) proposals.push_back(analogy_proposal(*analogy));
  if (asking.fleet != nullptr)
    for (DestinationProposal& p : asking.fleet->propose(key))
      if (goal_at(world, p.destination, object)) proposals.push_back(std::move(p));
  if (asking.llm)
    for (DestinationProposal& llm : llm_placements(world, object)) proposals.push_back(std::move(llm));
  for (const auto& [kind, refused] : refused_)
    if (kind == key.category) proposals = without_destination(proposals, refused);
  return proposals;
}

std::vector<DestinationProposal> GoalSources::llm_placements(const World& world, ObjectId object) const {
  std::vector<DestinationProposal> out;
  if (auto place = llm_preferences_.place_for(object)) {
    DestinationProposal proposal;
    proposal.destination = destination_at(world, *place);
    const std::optional<bool> kept = llm_preferences_.summary_keeps_examples();
    proposal.confidence = !rules_said_.empty() ? kLlmPlacementByPersonConfidence
                          : !kept              ? kLlmPlacementConfidence
                          : *kept              ? kLlmPlacementKeepingExamplesConfidence
                                               : kLlmPlacementLosingExamplesConfidence;
    proposal.source = ProposalSource::kLlmPlacement;
    const std::string& by = llm_preferences_.placed_by();
    proposal.reason = "the language model placed it" + (by.empty() ? std::string() : " by " + apprentice::quoted(by));
    out.push_back(std::move(proposal));
  }
  if (auto place = llm_preferences_.place_by_examples(object)) {
    DestinationProposal proposal;
    proposal.destination = destination_at(world, *place);
    proposal.confidence = kLlmByExamplesConfidence;
    proposal.source = ProposalSource::kLlmExamples;
    proposal.reason = "the language model placed it like the examples";
    out.push_back(std::move(proposal));
  }
  return out;
}

void GoalSources::consult_llm(LlmAdvisor& llm, const World& world, const std::vector<GoalKnowledge>& taught,
                              const std::vector<ObjectId>& things, const std::vector<ObjectId>& away_from,
                              const GoalScope& scope, const language::Lexicon& lexicon) {
  if (llm_preferences_.consulted() || !llm.knows_preference_prompts() || !llm.asking()) return;
  std::map<std::string, std::string> learned_as;
  for (const CategoryMatch& m : transfer_.matches()) learned_as[m.world] = m.learned;
  llm_preferences_.consult(llm, world, taught, learned_as, things, away_from, join(rules_said_, " "), lexicon);
  if (const auto& summary = llm_preferences_.summary_rule()) {
    spdlog::info("the LLM sums up what was taught: {}", llm_preferences_.summary());
    for (ClassRule& rule :
         class_rules_of(world, *summary, RuleSource::kLlm, llm_preferences_.summary(), scope, kLlmRuleConfidence))
      said_rules_.add(std::move(rule));
  }
}

void GoalSources::forget_rule(const ClassRule& rule) {
  said_rules_.remove(rule);
  proposer_.forget(rule);
}

std::vector<ClassRule> GoalSources::rules_in_use() const {
  std::vector<ClassRule> in_use;
  for (const ClassRule& rule : said_rules_.all())
    if (rule.source == RuleSource::kPerson) in_use.push_back(rule);
  for (const ClassRule& rule : proposer_.all_induced()) in_use.push_back(rule);
  return in_use;
}

std::optional<std::pair<Goal, std::string>> GoalSources::take_settled(ObjectId object) {
  auto settled = settled_.find(object);
  if (settled == settled_.end()) return std::nullopt;
  std::pair<Goal, std::string> out = std::move(settled->second);
  settled_.erase(settled);
  return out;
}

}  // namespace apprentice
