#include "knowledge/decision.h"

#include <algorithm>
#include <cmath>

namespace apprentice {

namespace {

// Probabilities are kept off 0 and 1 so that no one source can veto or
// settle everything: a source may be wrong.
constexpr double kFloor = 1e-6;

struct SourceBelief {
  ProposalSource source;
  std::vector<std::pair<Destination, double>> named;  // merged, scaled to sum at most 1
  double elsewhere = 0;                               // each place it did not name
};

std::vector<SourceBelief> by_source(std::span<const DestinationProposal> proposals, std::size_t place_count,
                                    const DecisionPolicy& policy) {
  std::vector<SourceBelief> sources;
  for (const DestinationProposal& p : proposals) {
    auto s = std::find_if(sources.begin(), sources.end(), [&](const SourceBelief& b) { return b.source == p.source; });
    if (s == sources.end()) s = sources.insert(sources.end(), SourceBelief{p.source, {}, 0});
    double confidence = std::clamp(policy.calibrated(p.source, p.confidence) * p.discount, kFloor, 1.0);
    auto d = std::find_if(s->named.begin(), s->named.end(), [&](const auto& n) { return n.first == p.destination; });
    if (d == s->named.end()) s->named.emplace_back(p.destination, confidence);
    else d->second = std::max(d->second, confidence);
  }
  for (SourceBelief& s : sources) {
    double total = 0;
    for (const auto& n : s.named) total += n.second;
    const std::size_t unnamed = place_count > s.named.size() ? place_count - s.named.size() : 0;
    if (total > 1 || unnamed == 0) {
      for (auto& n : s.named) n.second /= std::max(total, kFloor);
      total = 1;
    }
    s.elsewhere = unnamed ? std::max((1 - total) / static_cast<double>(unnamed), kFloor) : kFloor;
  }
  return sources;
}

}  // namespace

std::string_view proposal_source_name(ProposalSource source) {
  switch (source) {
    case ProposalSource::kMemory: return "memory";
    case ProposalSource::kSimilarity: return "similarity";
    case ProposalSource::kAnalogy: return "analogy";
    case ProposalSource::kInducedRule: return "induced rule";
    case ProposalSource::kPersonRule: return "person's rule";
    case ProposalSource::kLlmPlacement: return "llm placement";
    case ProposalSource::kLlmExamples: return "llm by examples";
    case ProposalSource::kLlmRule: return "llm summary";
    case ProposalSource::kFleet: return "fleet";
  }
  return "similarity";
}

ProposalSource proposal_source_of(RuleSource source) {
  switch (source) {
    case RuleSource::kInduced: return ProposalSource::kInducedRule;
    case RuleSource::kPerson: return ProposalSource::kPersonRule;
    case RuleSource::kLlm: return ProposalSource::kLlmRule;
    case RuleSource::kFleet: return ProposalSource::kFleet;
  }
  return ProposalSource::kInducedRule;
}

double Calibration::operator()(double confidence) const {
  if (shift == 0 && scale == 1) return confidence;
  const double p = std::clamp(confidence, kFloor, 1 - kFloor);
  return 1 / (1 + std::exp(-(shift + scale * std::log(p / (1 - p)))));
}

double DecisionPolicy::calibrated(ProposalSource source, double confidence) const {
  auto found = calibration.find(source);
  return found == calibration.end() ? confidence : found->second(confidence);
}

double DecisionPolicy::weight(ProposalSource source) const {
  auto found = weights.find(source);
  return found == weights.end() ? 1.0 : found->second;
}

std::vector<Belief> combine(std::span<const DestinationProposal> proposals, std::size_t place_count, const DecisionPolicy& policy) {
  std::vector<Belief> beliefs;
  for (const DestinationProposal& p : proposals) {
    auto b = std::find_if(beliefs.begin(), beliefs.end(), [&](const Belief& x) { return x.destination == p.destination; });
    if (b == beliefs.end()) b = beliefs.insert(beliefs.end(), Belief{p.destination, 0, {}});
    b->support.push_back(p);
  }
  if (beliefs.empty()) return beliefs;
  place_count = std::max(place_count, beliefs.size());
  std::vector<SourceBelief> sources = by_source(proposals, place_count, policy);
  // Log-scores of each named destination, and of any one place nobody named.
  std::vector<double> scores(beliefs.size(), 0.0);
  double unnamed_score = 0;
  for (const SourceBelief& s : sources) {
    const double w = policy.weight(s.source);
    unnamed_score += w * std::log(s.elsewhere);
    for (std::size_t i = 0; i < beliefs.size(); ++i) {
      auto n = std::find_if(s.named.begin(), s.named.end(), [&](const auto& x) { return x.first == beliefs[i].destination; });
      scores[i] += w * std::log(n == s.named.end() ? s.elsewhere : std::max(n->second, kFloor));
    }
  }
  double top = unnamed_score;
  for (double s : scores) top = std::max(top, s);
  const double unnamed_places = static_cast<double>(place_count - beliefs.size());
  double total = unnamed_places * std::exp(unnamed_score - top);
  for (double s : scores) total += std::exp(s - top);
  for (std::size_t i = 0; i < beliefs.size(); ++i) beliefs[i].probability = std::exp(scores[i] - top) / total;
  for (Belief& b : beliefs)
    std::stable_sort(b.support.begin(), b.support.end(),
                     [](const DestinationProposal& x, const DestinationProposal& y) { return x.confidence > y.confidence; });
  std::stable_sort(beliefs.begin(), beliefs.end(),
                   [](const Belief& x, const Belief& y) { return x.probability > y.probability; });
  return beliefs;
}

Decision decide(std::span<const DestinationProposal> proposals, std::size_t place_count, const DecisionPolicy& policy) {
  Decision decision;
  decision.beliefs = combine(proposals, place_count, policy);
  if (decision.beliefs.empty()) return decision;
  const Belief& best = decision.beliefs.front();
  decision.destination = best.destination;
  decision.confidence = best.probability;
  decision.support = best.support;
  std::vector<DestinationProposal> disputing;
  for (const DestinationProposal& p : proposals)
    if (std::find(policy.not_disputing.begin(), policy.not_disputing.end(), p.source) == policy.not_disputing.end()) {
      disputing.push_back(p);
      disputing.back().confidence = policy.calibrated(p.source, p.confidence) * p.discount;
    }
  decision.disputed = disputed(disputing, best.destination, policy.dispute_at);
  const double act_at = decision.disputed ? std::max(policy.act_at, policy.act_disputed_at) : policy.act_at;
  decision.kind = best.probability >= act_at             ? Decision::Kind::kAct
                  : best.probability >= policy.confirm_at ? Decision::Kind::kConfirm
                                                          : Decision::Kind::kAskWhere;
  return decision;
}

bool disputed(std::span<const DestinationProposal> proposals, const Destination& best, double at) {
  for (const DestinationProposal& p : proposals) {
    if (p.confidence < at || p.destination == best) continue;
    // The source's own best: no proposal of the same source surer of
    // another destination.
    const bool its_best = std::none_of(proposals.begin(), proposals.end(), [&](const DestinationProposal& q) {
      return q.source == p.source && q.confidence > p.confidence;
    });
    if (its_best) return true;
  }
  return false;
}

std::vector<DestinationProposal> without_destination(std::span<const DestinationProposal> proposals, const Destination& refused) {
  std::vector<DestinationProposal> out;
  for (const DestinationProposal& p : proposals)
    if (!(p.destination == refused)) out.push_back(p);
  return out;
}

}  // namespace apprentice
