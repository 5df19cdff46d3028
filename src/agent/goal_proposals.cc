#include "agent/goal_proposals.h"

#include <algorithm>
#include <set>

#include "knowledge/preferences.h"
#include "knowledge/said_rules.h"
#include "language/narration.h"
#include "util/text.h"

namespace apprentice {

DecisionPolicy default_decision_policy() {
  DecisionPolicy policy;
  policy.act_at = 0.9;
  policy.confirm_at = 0.25;
  // Where one source is fairly sure of another place (the LLM against the
  // examples' likeness), the agent acts alone only when the rest is very
  // sure: on the TidyBot benchmark's development half this kept wrong
  // placements with the LLM at 2.7% (from 3.3%; docs/benchmarks.md).
  policy.act_disputed_at = 0.95;
  policy.dispute_at = 0.5;
  // Likeness and the induced rules both read the same examples through the
  // same WordNet and vectors: not independent experts.
  policy.weights[ProposalSource::kSimilarity] = 0.45;
  policy.weights[ProposalSource::kInducedRule] = 0.45;
  // The LLM's summary as our reader applies it repeats what the LLM's own
  // placement by that summary says, less well.
  policy.weights[ProposalSource::kLlmRule] = 0.6;
  return policy;
}

GoalProposer::GoalProposer(const ConceptSource& concepts, std::vector<GoalKnowledge> prior, std::set<std::string> forgotten)
    : concepts_(&concepts), prior_(std::move(prior)), forgotten_(std::move(forgotten)) {}

std::vector<const GoalKnowledge*> GoalProposer::prior_for(const GoalKey& key) const {
  auto pick = [&](auto&& fits) {
    std::vector<const GoalKnowledge*> out;
    for (const GoalKnowledge& g : prior_)
      if (g.key.category != key.category && fits(g.key) && destination_of(g.literals)) out.push_back(&g);
    return out;
  };
  auto same_context = pick([&](const GoalKey& k) {
    return k.task == key.task && k.subtask == key.subtask && k.place == key.place;
  });
  if (!same_context.empty()) return same_context;
  auto same_task = pick([&](const GoalKey& k) { return k.task == key.task; });
  if (!same_task.empty()) return same_task;
  return pick([](const GoalKey&) { return true; });
}

std::vector<PlacementExample> GoalProposer::examples_for(const GoalKey& key) const {
  std::vector<PlacementExample> examples;
  std::set<std::string> kinds;
  for (const GoalKnowledge* g : prior_for(key)) {
    // One example per kind: the same kind learned in several contexts is
    // one piece of evidence.
    if (!kinds.insert(g->key.category).second) continue;
    examples.push_back(PlacementExample{concepts_->profile(g->key.category), *destination_of(g->literals)});
  }
  return examples;
}

namespace {

std::string scope_key(const std::vector<const GoalKnowledge*>& prior) {
  std::string key;
  for (const GoalKnowledge* g : prior) key += g->key.task + "|" + g->key.subtask + "|" + g->key.place + "|" + g->key.category + ";";
  return key;
}

}  // namespace

const std::vector<ClassRule>& GoalProposer::induced_for(const GoalKey& key) const {
  std::vector<const GoalKnowledge*> prior = prior_for(key);
  const std::string scope = scope_key(prior);
  if (auto known = induced_.find(scope); known != induced_.end()) return known->second;
  GoalScope where;
  if (!prior.empty()) where = GoalScope{prior.front()->key.task, prior.front()->key.subtask, prior.front()->key.place};
  std::vector<ClassRule> rules = induce_rules(examples_for(key), where);
  std::erase_if(rules, [&](const ClassRule& rule) { return forgotten_.contains(class_rule_key(rule)); });
  return induced_.emplace(scope, std::move(rules)).first->second;
}

void GoalProposer::forget(const ClassRule& rule) {
  forgotten_.insert(class_rule_key(rule));
  induced_.clear();
}

std::vector<ClassRule> GoalProposer::all_induced() const {
  std::vector<ClassRule> out;
  std::set<std::string> seen;
  for (const GoalKnowledge& g : prior_) {
    GoalKey key = g.key;
    key.category = "";  // a kind nothing was taught for: every example counts
    const std::string scope = key.task + "|" + key.subtask + "|" + key.place;
    if (!seen.insert(scope).second) continue;
    for (const ClassRule& rule : induced_for(key)) out.push_back(rule);
  }
  return out;
}

std::vector<DestinationProposal> GoalProposer::propose(const World& world, const GoalKey& key, ObjectId object,
                                                       std::span<const ClassRule> said) const {
  KindProfile thing = concepts_->profile(key.category);
  std::vector<DestinationProposal> out;
  std::vector<PlacementExample> examples = examples_for(key);
  const std::vector<ClassRule>& induced = induced_for(key);
  // Likeness tells destinations apart: with examples at one destination
  // alone it cannot say whether a thing goes there or anywhere else.
  std::set<std::string> destinations;
  for (const PlacementExample& e : examples) destinations.insert(format_destination(e.destination));
  if (destinations.size() >= 2)
    for (DestinationProposal& p : likeness_proposals(examples, thing, induced, *concepts_)) out.push_back(std::move(p));
  if (!examples.empty()) {
    for (DestinationProposal& p : rule_proposals(induced, thing, RuleSource::kInduced)) out.push_back(std::move(p));
  }
  // Examples taught for another task are half as telling (as analogies
  // from another context are: agent/transfer.h): the same person may want
  // the soda can in the recycling bin after a meal and in the fridge after
  // shopping.
  const std::vector<const GoalKnowledge*> prior = prior_for(key);
  if (!prior.empty() && prior.front()->key.task != key.task)
    for (DestinationProposal& p : out) p.discount = 0.5;
  // The person's rules and the LLM's summary's, where said for this task
  // (or before any task).
  std::vector<ClassRule> applicable;
  for (const ClassRule& rule : said)
    if (rule.scope.task.empty() || rule.scope.task == key.task) applicable.push_back(rule);
  for (RuleSource source : {RuleSource::kPerson, RuleSource::kLlm})
    for (DestinationProposal& p : said_rule_proposals(applicable, thing, source, *concepts_))
      if (!lacks_a_property_said(world, object, p)) out.push_back(std::move(p));
  std::erase_if(out, [&](const DestinationProposal& p) { return !goal_at(world, p.destination, object); });
  return out;
}

bool lacks_a_property_said(const World& world, ObjectId object, const DestinationProposal& proposal) {
  if (!proposal.rule) return false;
  std::vector<std::string> words = proposal.rule->modifiers;
  const std::vector<std::string> class_words = split_words(proposal.rule->class_name);
  if (class_words.size() > 1) words.insert(words.end(), class_words.begin(), class_words.end() - 1);
  const std::vector<std::string>& has = world.universe->info(object).properties;
  const std::vector<std::string> name = language::name_parts(world.universe->info(object).category);
  for (const std::string& word : words) {
    if (std::find(has.begin(), has.end(), word) != has.end() || std::find(name.begin(), name.end(), word) != name.end())
      continue;
    // A property the world gives some thing, which this one lacks.
    for (ObjectId other : world.universe->of_kind(ObjectKind::kItem)) {
      const std::vector<std::string>& theirs = world.universe->info(other).properties;
      if (std::find(theirs.begin(), theirs.end(), word) != theirs.end()) return true;
    }
  }
  return false;
}

std::optional<Goal> goal_at(const World& world, const Destination& destination, ObjectId object) {
  GoalKnowledge placement;
  placement.literals = destination_literals(destination);
  return instantiate_goal(world, placement, object);
}

std::size_t place_count(const World& world, std::span<const ObjectId> away_from) {
  std::size_t count = 0;
  for (ObjectKind kind : {ObjectKind::kReceptacle, ObjectKind::kSurface})
    for (ObjectId place : world.universe->of_kind(kind))
      if (std::find(away_from.begin(), away_from.end(), place) == away_from.end()) ++count;
  return count;
}

std::string evidence_phrase(const World& world, std::span<const DestinationProposal> support) {
  std::vector<std::string> said, like;
  bool llm = false;
  const DestinationProposal* fleet = nullptr;
  for (const DestinationProposal& p : support) {
    if (p.source == ProposalSource::kPersonRule && p.rule && !p.rule->said.empty()) {
      std::string subject = rule_subject(*p.rule);
      // A kind here said in the singular ("sticky note goes in the
      // wastebasket"): "with the sticky note".
      std::string as_kind = subject;
      std::replace(as_kind.begin(), as_kind.end(), ' ', '-');
      if (!language::is_plural_category(as_kind) && !world.universe->with_category(as_kind).empty())
        subject = "the " + subject;
      if (std::find(said.begin(), said.end(), subject) == said.end()) said.push_back(subject);
    }
    else if (p.source == ProposalSource::kFleet) fleet = fleet != nullptr ? fleet : &p;
    else if (p.source == ProposalSource::kLlmPlacement || p.source == ProposalSource::kLlmExamples ||
             p.source == ProposalSource::kLlmRule) llm = true;
    else
      for (const std::string& kind : p.evidence)
        if (like.size() < 2 && std::find(like.begin(), like.end(), kind) == like.end()) like.push_back(kind);
  }
  // The class said, so that a person can tell whether the thing is one
  // ("Does the paint pot go with brushes, as you said: ...?").
  if (!said.empty()) return "with " + language::list_phrase(said) + ", as you said";
  if (!like.empty()) {
    std::vector<std::string> names;
    for (const std::string& kind : like) names.push_back("the " + language::spoken_category(kind));
    return "like " + language::list_phrase(names);
  }
  if (llm) return "as the language model suggests";
  if (fleet != nullptr) return "as " + fleet_phrase(*fleet);
  return "";
}

std::string fleet_phrase(const DestinationProposal& fleet) {
  const std::string chose = std::to_string(fleet.households), of = std::to_string(fleet.of_households);
  if (fleet.of_households == 1) return "in the one other household I know of";
  if (fleet.households == fleet.of_households) return "in all " + of + " other households I know of";
  if (2 * fleet.households > fleet.of_households) return "in most households I know of (" + chose + " of " + of + ")";
  return "in " + chose + " of the " + of + " other households I know of";
}

std::string rule_subject(const ClassRule& rule) {
  std::string what = rule.class_name;
  if (!rule.modifiers.empty()) what = join(rule.modifiers, " ") + (what.empty() ? " things" : " " + what);
  if (what.empty()) return rule.rest ? "everything else" : "everything";
  return rule.rest ? "other " + what : what;
}

std::string say_class_rule(const ClassRule& rule) {
  const std::string what = rule_subject(rule);
  std::string place = rule.destination.place.category;
  for (auto p = rule.destination.place.properties.rbegin(); p != rule.destination.place.properties.rend(); ++p)
    place = *p + " " + place;
  std::string out = what + " " + (language::is_plural_category(what) ? "go " : "goes ") + rule.destination.relation +
                    " the " + language::spoken_category(place);
  for (const GoalTemplateLiteral& door : rule.destination.doors)
    if (door.predicate == "closed" && door.positive) out += ", and the " + language::spoken_category(place) + " ends closed";
  if (!rule.exceptions.empty()) {
    std::vector<std::string> but;
    for (const std::string& kind : rule.exceptions) but.push_back("the " + language::spoken_category(kind));
    out += ", except " + language::list_phrase(but);
  }
  std::vector<std::string> from;
  for (const std::string& kind : rule.evidence) from.push_back("the " + language::spoken_category(kind));
  const int sure = static_cast<int>(rule.confidence * 100 + 0.5);
  switch (rule.source) {
    case RuleSource::kInduced:
      out += ", from " + language::list_phrase(from) + " (induced from the examples, " + std::to_string(sure) + "% sure)";
      break;
    case RuleSource::kPerson: out += ", as said: \"" + rule.said + "\""; break;
    case RuleSource::kLlm: out += ", as the language model summed up: \"" + rule.said + "\""; break;
    case RuleSource::kFleet: out += ", as other robots learned"; break;
  }
  return out;
}

std::vector<std::string> explain_preferences(const Knowledge& knowledge, const ConceptSource& concepts) {
  GoalProposer proposer(concepts, knowledge.goals.all());
  std::vector<std::string> out;
  for (const ClassRule& rule : proposer.all_induced()) out.push_back(say_class_rule(rule));
  return out;
}

}  // namespace apprentice
