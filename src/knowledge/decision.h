// Deciding where a thing goes from what several knowledge sources propose.
//
// Each source proposes destinations for one thing, each with the source's
// own probability that the thing goes there: the agent's memory of the
// kind, the class rules that cover it (induced, the person's, an LLM's
// summary), its likeness to the things taught (WordNet's hierarchy and the
// word vectors), an LLM's placement, what other households chose
// (knowledge/fleet_prior.h). The agent
// combines them (combine) and acts alone when the combined belief is high
// enough; otherwise it asks one yes/no question that shows its evidence, or,
// when nothing is likely, where the thing goes (decide).
//
// The combination treats the sources as independent experts over the same
// set of places (a product of their distributions, each raised to a weight
// that discounts sources which share their evidence): a source's proposals
// for some destinations leave the rest of its belief spread evenly over the
// places it did not name. Calibrated on data: docs/benchmarks.md.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "knowledge/preferences.h"

namespace apprentice {

enum class ProposalSource {
  kMemory,        // the goal learned for this very kind
  kSimilarity,    // likeness to the kinds taught: WordNet's classes and the vectors (knowledge/likeness.h)
  kAnalogy,       // WordNet's nearest kind learned before (agent/transfer.h)
  kInducedRule,   // a class rule induced from the examples
  kPersonRule,    // a class rule the person said
  kLlmPlacement,  // the LLM placed the thing (by its summary, or by the person's rule)
  kLlmExamples,   // the LLM placed the thing by the examples alone, without a summary
  kLlmRule,       // a class rule read from the LLM's summary
  kFleet,         // other robots' knowledge
};
// "memory", "similarity", "analogy", "induced rule", "person's rule", "llm placement",
// "llm by examples", "llm summary", "fleet".
std::string_view proposal_source_name(ProposalSource source);
// The source a class rule's proposals come from: induced, the person's, the
// LLM's summary, the fleet's.
ProposalSource proposal_source_of(RuleSource source);

struct DestinationProposal {
  Destination destination;
  // The source's probability that the thing goes there, in (0, 1].
  double confidence = 0;
  ProposalSource source = ProposalSource::kSimilarity;
  // The kinds taught that support it, nearest first ("banana", "apple"):
  // what the question shows ("with the banana and the apple").
  std::vector<std::string> evidence;
  // The class rule it came from, when one did: a "no" becomes an exception
  // to it.
  std::optional<ClassRule> rule;
  // One line for logs and reports: "edible fruit, like the banana and the
  // apple".
  std::string reason;
  // The fleet's (knowledge/fleet_prior.h): how many other households put
  // the kind there, of how many that taught it.
  std::size_t households = 0, of_households = 0;
  // The share of its chance, once calibrated (DecisionPolicy::calibration),
  // that the proposal keeps: less than 1 for evidence from elsewhere (the
  // examples of another task count half, agent/goal_proposals.h). Applied
  // after the calibration, so that a calibration that flattens a source's
  // confidences does not erase it.
  double discount = 1;
};

// The combined belief in one destination.
struct Belief {
  Destination destination;
  double probability = 0;
  // The proposals for it, most confident first.
  std::vector<DestinationProposal> support;
};

// A source's confidence mapped to the chance that its proposal is right,
// in log-odds: logit(p') = shift + scale * logit(p) (Platt's scaling). The
// identity (shift 0, scale 1) trusts the source's own figure; scale 0 gives
// every proposal of the source the same chance, sigmoid(shift).
struct Calibration {
  double shift = 0;
  double scale = 1;
  double operator()(double confidence) const;
};

struct DecisionPolicy {
  // Acts alone when the best destination's combined probability is at least
  // this.
  double act_at = 0.9;
  // Below act_at, asks yes/no about the best destination when its
  // probability is at least this; else asks where the thing goes.
  double confirm_at = 0.25;
  // A disputed decision acts alone only from this belief (at least
  // act_at): one where some source is at least `dispute_at` sure of
  // another destination than the best. Sources that disagree are the
  // sign of a mistake (the LLM's placement against the examples' likeness),
  // so the agent asks rather than outvote one of them; 0 (the default):
  // no difference.
  double act_disputed_at = 0;
  double dispute_at = 0.5;
  // Sources whose disagreement is no dispute (the person's rule as our
  // reader applies it, where the LLM placed the thing by the same words).
  std::vector<ProposalSource> not_disputing;
  // Each source's weight in the product (its exponent): 1 trusts it as an
  // independent expert, less discounts it. A source not named weighs 1.
  std::map<ProposalSource, double> weights;
  double weight(ProposalSource source) const;
  // Each source's confidences as chances, before they are combined and
  // before a dispute is looked for. A source not named keeps its own.
  std::map<ProposalSource, Calibration> calibration;
  double calibrated(ProposalSource source, double confidence) const;
};

// The combined belief over the destinations proposed, most probable first.
// `place_count` is how many places the thing could go to in this world (at
// least the number of distinct destinations proposed): the belief a source
// did not give to the destinations it named is spread over the rest, and a
// place no source names keeps its share of the total (so a lone proposal at
// 0.5 among four places combines to 0.5, not 1). A source's proposals for
// one destination are merged (the most confident kept), and a source whose
// proposals sum past 1 is scaled down to 1. Empty when nothing is proposed.
std::vector<Belief> combine(std::span<const DestinationProposal> proposals, std::size_t place_count,
                            const DecisionPolicy& policy);

struct Decision {
  enum class Kind {
    kAct,       // confident: act alone
    kConfirm,   // in doubt: ask yes/no about `destination`, showing `support`
    kAskWhere,  // nothing is likely: ask where the thing goes
  };
  Kind kind = Kind::kAskWhere;
  // The most probable destination (kAct, kConfirm); nullopt for kAskWhere
  // when nothing was proposed.
  std::optional<Destination> destination;
  double confidence = 0;
  std::vector<DestinationProposal> support;
  // The whole belief, most probable first, for reports and the next
  // question after a "no".
  std::vector<Belief> beliefs;
  // Some source is at least DecisionPolicy::dispute_at sure of another
  // destination (kAct then needs act_disputed_at).
  bool disputed = false;
};

Decision decide(std::span<const DestinationProposal> proposals, std::size_t place_count, const DecisionPolicy& policy);

// The proposals without those for a destination the teacher refused for
// this thing (after a "no", the next question is about what is left).
// Whether some source's most confident proposal, at `at` or more, is for
// another destination than `best`.
bool disputed(std::span<const DestinationProposal> proposals, const Destination& best, double at);

std::vector<DestinationProposal> without_destination(std::span<const DestinationProposal> proposals, const Destination& refused);

}  // namespace apprentice
