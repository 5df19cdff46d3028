// The LLM's placements in the session (agent/llm_preferences.h): asked once,
// each a proposal that the decision weighs with the other sources
// (agent_decision.cc).
#include <algorithm>

#include "agent/person_rule.h"
#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

void TaskLearningAgent::Session::consult_llm(ObjectId object) {
  if (agent_.llm_ == nullptr || !agent_.options_.condition.llm || llm_preferences_.consulted()) return;
  LlmAdvisor& llm = *agent_.llm_;
  if (!llm.knows_preference_prompts() || !llm.asking()) return;
  const World& w = world();
  std::vector<ObjectId> things;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (o == object || still_to_come(o)) things.push_back(o);
  std::vector<GoalKnowledge> taught;
  for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
    if (g.key.task == progress_.task.name) taught.push_back(g);
  std::map<std::string, std::string> learned_as;
  for (const CategoryMatch& m : transfer_.matches()) learned_as[m.world] = m.learned;
  llm_preferences_.consult(llm, w, taught, learned_as, things, current().places, join(rules_said_, " "),
                           agent_.understanding_.lexicon());
  if (const auto& summary = llm_preferences_.summary_rule()) {
    spdlog::info("the LLM sums up what was taught: {}", llm_preferences_.summary());
    for (ClassRule& rule : class_rules_of(w, *summary, RuleSource::kLlm, llm_preferences_.summary(), said_scope(),
                                          kLlmRuleConfidence))
      said_rules_.add(std::move(rule));
  }
}

namespace {

// On the TidyBot benchmark's development half (docs/benchmarks.md, "The
// LLM's placements weighed"): the LLM's placement by its own summary was
// right for 96% of the unseen objects where that summary, given back to
// it, put every example where it was taught, and for 82% where it lost
// one; its placement from the examples alone, for 75%.
constexpr double kLlmPlacementKeepingExamplesConfidence = 0.95;
constexpr double kLlmPlacementLosingExamplesConfidence = 0.85;
constexpr double kLlmByExamplesConfidence = 0.75;

}  // namespace

std::vector<DestinationProposal> TaskLearningAgent::Session::llm_placement_proposals(ObjectId object) const {
  std::vector<DestinationProposal> out;
  if (auto place = llm_preferences_.place_for(object)) {
    DestinationProposal proposal;
    proposal.destination = destination_at(world(), *place);
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
    proposal.destination = destination_at(world(), *place);
    proposal.confidence = kLlmByExamplesConfidence;
    proposal.source = ProposalSource::kLlmExamples;
    proposal.reason = "the language model placed it like the examples";
    out.push_back(std::move(proposal));
  }
  return out;
}

}  // namespace apprentice
