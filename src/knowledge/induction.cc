#include "knowledge/induction.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "util/text.h"

namespace apprentice {

namespace {

// The weight a thing's classes give a class id (0 if not among them).
double class_weight(const KindProfile& thing, const std::string& id) {
  double best = 0;
  for (const ConceptClass& c : thing.classes)
    if (c.id == id) best = std::max(best, c.weight);
  return best;
}

bool has_modifiers(const KindProfile& thing, const std::vector<std::string>& modifiers) {
  for (const std::string& m : modifiers)
    if (std::find(thing.modifiers.begin(), thing.modifiers.end(), m) == thing.modifiers.end()) return false;
  return true;
}

struct Hypothesis {
  const ConceptClass* cls = nullptr;
  double log_likelihood = 0;
  double posterior = 0;
};

// Destinations in the order their first example came.
std::vector<Destination> destinations_of(std::span<const PlacementExample> examples) {
  std::vector<Destination> out;
  for (const PlacementExample& e : examples)
    if (std::find(out.begin(), out.end(), e.destination) == out.end()) out.push_back(e.destination);
  return out;
}

// Modifiers every example of the destination has (two or more of them)
// and no example of another destination has: one rule of them all.
std::optional<ClassRule> modifier_rule(std::span<const PlacementExample> examples, const Destination& destination,
                                       const GoalScope& scope) {
  std::vector<const PlacementExample*> mine, others;
  for (const PlacementExample& e : examples) (e.destination == destination ? mine : others).push_back(&e);
  if (mine.size() < 2) return std::nullopt;
  std::vector<std::string> shared = mine.front()->thing.modifiers;
  for (const PlacementExample* e : mine)
    std::erase_if(shared, [&](const std::string& m) { return !has_modifiers(e->thing, {m}); });
  std::erase_if(shared, [&](const std::string& m) {
    return std::any_of(others.begin(), others.end(), [&](const PlacementExample* o) { return has_modifiers(o->thing, {m}); });
  });
  if (shared.empty()) return std::nullopt;
  ClassRule rule;
  rule.modifiers = shared;
  rule.destination = destination;
  rule.source = RuleSource::kInduced;
  for (const PlacementExample* e : mine) rule.evidence.push_back(e->thing.kind);
  // Laplace's rule of succession: n examples, none against.
  const double n = static_cast<double>(mine.size());
  rule.confidence = n / (n + 1);
  rule.scope = scope;
  return rule;
}

// The class rules of one destination, by the size principle.
std::vector<ClassRule> class_rules(std::span<const PlacementExample> examples, const Destination& destination,
                                   const GoalScope& scope, const InductionOptions& options) {
  std::vector<const PlacementExample*> mine, others;
  for (const PlacementExample& e : examples) (e.destination == destination ? mine : others).push_back(&e);
  std::map<std::string, Hypothesis> hypotheses;
  for (const PlacementExample* e : mine)
    for (const ConceptClass& c : e->thing.classes) {
      Hypothesis& h = hypotheses[c.id];
      if (h.cls == nullptr || c.depth < h.cls->depth) h.cls = &c;
    }
  if (hypotheses.empty()) return {};
  const double outlier = options.outlier / options.universe;
  double best = -INFINITY;
  for (auto& [id, h] : hypotheses) {
    const double size = std::max(h.cls->size, 1.0);
    for (const PlacementExample* e : mine)
      h.log_likelihood += std::log((1 - options.outlier) * class_weight(e->thing, id) / size + outlier);
    best = std::max(best, h.log_likelihood);
  }
  double total = 0;
  for (auto& [id, h] : hypotheses) total += h.posterior = std::exp(h.log_likelihood - best);
  std::vector<const Hypothesis*> ranked;
  for (auto& [id, h] : hypotheses) {
    h.posterior /= total;
    ranked.push_back(&h);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const Hypothesis* a, const Hypothesis* b) {
    if (a->posterior != b->posterior) return a->posterior > b->posterior;
    return a->cls->size < b->cls->size;
  });
  std::vector<ClassRule> rules;
  for (const Hypothesis* h : ranked) {
    if (rules.size() >= options.max_rules_per_destination || h->posterior < options.min_confidence) break;
    // One example's own sense is that example, not a class: memory has it.
    const auto covered = std::count_if(mine.begin(), mine.end(),
                                       [&](const PlacementExample* e) { return class_weight(e->thing, h->cls->id) > 0; });
    if (covered < 2 && h->cls->depth == 0) continue;
    ClassRule rule;
    rule.class_name = h->cls->name;
    rule.class_id = h->cls->id;
    rule.destination = destination;
    rule.source = RuleSource::kInduced;
    for (const PlacementExample* e : mine)
      if (class_weight(e->thing, h->cls->id) > 0) rule.evidence.push_back(e->thing.kind);
    rule.confidence = h->posterior;
    rule.scope = scope;
    rules.push_back(std::move(rule));
  }
  return rules;
}

}  // namespace

namespace {

// The size of a rule's class as a thing's profile gives it (0 if the thing
// is not of the class).
double size_for(const ClassRule& rule, const KindProfile& thing) {
  for (const ConceptClass& c : thing.classes)
    if (c.id == rule.class_id) return std::max(c.size, 1.0);
  return 0;
}

// A class rule of one destination that also covers things taught to go
// elsewhere: where each of those is covered there by a smaller class, this
// rule is what the other rules leave of its class ("other food"); the
// others are exceptions to it.
void mark_rest_and_exceptions(std::vector<ClassRule>& rules, std::span<const PlacementExample> examples) {
  for (ClassRule& rule : rules) {
    if (rule.class_id.empty()) continue;
    for (const PlacementExample& o : examples) {
      if (o.destination == rule.destination) continue;
      const double size = size_for(rule, o.thing);
      if (size == 0) continue;
      // A narrower class of two or more things taught there, not one
      // thing's own kind.
      bool narrower_there = std::any_of(rules.begin(), rules.end(), [&](const ClassRule& r) {
        return r.destination == o.destination && !r.class_id.empty() && r.evidence.size() >= 2 &&
               size_for(r, o.thing) > 0 && size_for(r, o.thing) < size;
      });
      if (narrower_there) rule.rest = true;
      else if (std::find(rule.exceptions.begin(), rule.exceptions.end(), o.thing.kind) == rule.exceptions.end())
        rule.exceptions.push_back(o.thing.kind);
    }
  }
}

}  // namespace

std::vector<ClassRule> induce_rules(std::span<const PlacementExample> examples, const GoalScope& scope,
                                    const InductionOptions& options) {
  std::vector<ClassRule> rules;
  for (const Destination& destination : destinations_of(examples)) {
    if (auto rule = modifier_rule(examples, destination, scope)) rules.push_back(std::move(*rule));
    for (ClassRule& rule : class_rules(examples, destination, scope, options)) rules.push_back(std::move(rule));
  }
  mark_rest_and_exceptions(rules, examples);
  return rules;
}

double rule_covers(const ClassRule& rule, const KindProfile& thing) {
  if (std::find(rule.exceptions.begin(), rule.exceptions.end(), thing.kind) != rule.exceptions.end()) return 0;
  if (!has_modifiers(thing, rule.modifiers)) return 0;
  if (rule.class_name.empty() && rule.class_id.empty()) return 1;
  if (!rule.class_id.empty()) return class_weight(thing, rule.class_id);
  double best = 0;
  for (const ConceptClass& c : thing.classes)
    if (c.name == rule.class_name) best = std::max(best, c.weight);
  return best;
}

std::vector<DestinationProposal> rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing, RuleSource source,
                                     const InductionOptions& options) {
  struct Share {
    Destination destination;
    double score = 0;
    std::vector<const ClassRule*> covering;
  };
  std::vector<Share> shares;
  auto share_of = [&](const Destination& d) -> Share& {
    auto s = std::find_if(shares.begin(), shares.end(), [&](const Share& x) { return x.destination == d; });
    if (s == shares.end()) s = shares.insert(shares.end(), Share{d, options.outlier / options.universe, {}});
    return *s;
  };
  bool covered_by_other = false;
  for (const ClassRule& rule : rules) {
    if (rule.source != source) continue;
    share_of(rule.destination);
    if (!rule.rest && rule_covers(rule, thing) > 0) covered_by_other = true;
  }
  for (const ClassRule& rule : rules) {
    if (rule.source != source || (rule.rest && covered_by_other)) continue;
    const double weight = rule_covers(rule, thing);
    if (weight <= 0) continue;
    double size = 1;
    if (!rule.class_id.empty() || !rule.class_name.empty())
      for (const ConceptClass& c : thing.classes)
        if (c.id == rule.class_id || (rule.class_id.empty() && c.name == rule.class_name)) size = std::max(c.size, 1.0);
    Share& s = share_of(rule.destination);
    s.score += rule.confidence * weight / size;
    s.covering.push_back(&rule);
  }
  double total = 0;
  for (const Share& s : shares) total += s.score;
  std::vector<DestinationProposal> out;
  for (const Share& s : shares) {
    if (s.covering.empty()) continue;
    DestinationProposal p;
    p.destination = s.destination;
    const ClassRule* strongest = s.covering.front();
    for (const ClassRule* r : s.covering)
      if (r->confidence > strongest->confidence) strongest = r;
    // The destination's share among those the rules name, no surer than
    // its strongest rule is of its class (one destination alone is not
    // certain).
    p.confidence = s.score / total * strongest->confidence;
    p.source = proposal_source_of(source);
    p.rule = *strongest;
    p.evidence = strongest->evidence;
    p.reason = format_class_rule(*strongest);
    out.push_back(std::move(p));
  }
  std::stable_sort(out.begin(), out.end(), [](const DestinationProposal& a, const DestinationProposal& b) { return a.confidence > b.confidence; });
  return out;
}

}  // namespace apprentice
