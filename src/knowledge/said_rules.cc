#include "knowledge/said_rules.h"

#include <algorithm>
#include <cmath>

#include "util/cosine.h"
#include "util/text.h"

namespace apprentice {

namespace {

bool in_name(const KindProfile& thing, const std::string& word) {
  if (std::find(thing.modifiers.begin(), thing.modifiers.end(), word) != thing.modifiers.end()) return true;
  for (const std::string& w : split_words(thing.head))
    if (w == word) return true;
  return false;
}

bool wordnet_covers(const ClassRule& rule, const KindProfile& thing, const ConceptSource& concepts) {
  if (!rule.class_id.empty())
    return std::any_of(thing.classes.begin(), thing.classes.end(), [&](const ConceptClass& c) { return c.id == rule.class_id; });
  if (rule.class_name.empty()) return false;
  for (const ConceptClass& said : concepts.classes_named(rule.class_name))
    for (const ConceptClass& c : thing.classes)
      if (c.id == said.id) return true;
  return false;
}

// How well the thing fits the rule's class, before the clauses compete;
// `sure` is set when WordNet or the thing's own words put it in the class.
double class_score(const ClassRule& rule, const KindProfile& thing, const ConceptSource& concepts,
                   const SaidRuleWeights& weights, bool& sure) {
  double score = 0;
  sure = false;
  std::vector<std::string> words = rule.modifiers;
  if (!rule.class_name.empty()) {
    words.push_back(rule.class_name);
    if (wordnet_covers(rule, thing, concepts)) {
      score += weights.wordnet;
      sure = true;
    }
  }
  if (!rule.modifiers.empty()) {
    const bool all = std::all_of(rule.modifiers.begin(), rule.modifiers.end(),
                                 [&](const std::string& m) { return in_name(thing, m); });
    if (all) score += weights.modifier;
    sure = sure && all;
    if (all && rule.class_name.empty()) sure = true;
    if (!all && !rule.class_name.empty()) score -= weights.modifier_missing;
  }
  if (!thing.vector.empty()) {
    std::vector<float> phrase = concepts.vector_of(join(words, " "));
    if (!phrase.empty()) score += weights.vector * cosine(thing.vector, phrase);
  }
  return score;
}

}  // namespace

std::vector<DestinationProposal> said_rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing,
                                                     RuleSource source, const ConceptSource& concepts,
                                                     const SaidRuleWeights& weights) {
  std::vector<const ClassRule*> mine;
  for (const ClassRule& rule : rules)
    if (rule.source == source &&
        std::find(rule.exceptions.begin(), rule.exceptions.end(), thing.kind) == rule.exceptions.end())
      mine.push_back(&rule);
  if (mine.empty()) return {};
  // A rule for the rest takes the thing only when no other clause is sure
  // of it ("outerwear in the closet and other clothes on the bed": the
  // parka is outerwear).
  std::vector<double> scores(mine.size(), 0.0);
  bool another_is_sure = false;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    if (mine[i]->rest) continue;
    bool sure = false;
    scores[i] = class_score(*mine[i], thing, concepts, weights, sure);
    another_is_sure = another_is_sure || sure;
  }
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const ClassRule& rule = *mine[i];
    if (!rule.rest) continue;
    bool sure = false;
    const double own = rule.class_name.empty() && rule.modifiers.empty() ? weights.rest
                                                                         : class_score(rule, thing, concepts, weights, sure);
    scores[i] = own - (another_is_sure ? weights.rest_penalty : 0.0);
  }
  const double top = std::max(*std::max_element(scores.begin(), scores.end()), weights.none);
  double total = std::exp(weights.none - top);
  for (double& s : scores) total += s = std::exp(s - top);
  std::vector<DestinationProposal> out;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const ClassRule& rule = *mine[i];
    const double share = scores[i] / total;
    auto same = std::find_if(out.begin(), out.end(), [&](const DestinationProposal& p) { return p.destination == rule.destination; });
    if (same != out.end()) {
      same->confidence += share * rule.confidence;
      continue;
    }
    DestinationProposal p;
    p.destination = rule.destination;
    p.confidence = share * rule.confidence;
    p.source = proposal_source_of(source);
    p.rule = rule;
    p.evidence = rule.evidence;
    p.reason = format_class_rule(rule);
    out.push_back(std::move(p));
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const DestinationProposal& a, const DestinationProposal& b) { return a.confidence > b.confidence; });
  return out;
}

}  // namespace apprentice
