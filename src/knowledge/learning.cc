#include "knowledge/learning.h"

#include <algorithm>
#include <map>
#include <set>

namespace apprentice {

const char* to_string(Generalization generalization) {
  return generalization == Generalization::kPaper ? "paper" : "full";
}

Result<Generalization> parse_generalization(std::string_view text) {
  if (text == "full") return Generalization::kFull;
  if (text == "paper") return Generalization::kPaper;
  return make_error(ErrorCode::kInvalidInput, "generalization must be full or paper, not '" + std::string(text) + "'");
}

namespace {

bool contains(const std::vector<Fact>& facts, const Fact& fact) {
  return std::find(facts.begin(), facts.end(), fact) != facts.end();
}

// Turns ground literals and an action into a rule over variables.
class Variablizer {
 public:
  Variablizer(const Universe& universe, const Episode& episode, Generalization generalization)
      : universe_(universe), episode_(episode), generalization_(generalization) {}

  Rule make_rule(const Domain& domain, const std::set<Literal>& conditions, const Action& action,
                 int steps, const std::string& source) {
    rule_ = Rule();
    ids_.clear();
    variable_of(episode_.object_of_interest);  // always ?o, always variable 0
    for (const Literal& l : episode_.goal.literals) rule_.goal.push_back(pattern(l));
    for (const Literal& l : conditions) rule_.conditions.push_back(pattern(l));
    rule_.action = action.schema;
    for (ObjectId o : action.arguments()) rule_.action_args.push_back(variable_of(o));
    rule_.steps_to_goal = steps;
    if (generalization_ == Generalization::kPaper) {
      // As in the paper's chunks: the subtask is tested, and so is the
      // category of each object the action manipulates besides the object
      // of interest (Open(O1) with category(O1) = dishwasher).
      rule_.subtask = episode_.subtask;
      for (const auto& [object, variable] : ids_) {
        RuleVariable& v = rule_.variables[variable];
        bool acted_on = std::find(rule_.action_args.begin(), rule_.action_args.end(), variable) != rule_.action_args.end();
        if (acted_on && !v.object_of_interest) v.category = universe_.info(object).category;
      }
    }
    rule_.provenance = Provenance{episode_.object_description, source};
    std::sort(rule_.goal.begin(), rule_.goal.end());
    std::sort(rule_.conditions.begin(), rule_.conditions.end());
    (void)domain;
    return rule_;
  }

 private:
  VariableId variable_of(ObjectId object) {
    auto it = ids_.find(object);
    if (it != ids_.end()) return it->second;
    const ObjectInfo& info = universe_.info(object);
    RuleVariable v;
    v.object_of_interest = object == episode_.object_of_interest;
    std::string base = v.object_of_interest ? "?o"
                       : info.kind == ObjectKind::kReceptacle ? "?r"
                       : info.kind == ObjectKind::kSurface ? "?s"
                                                           : "?x";
    int same = 0;
    for (const RuleVariable& other : rule_.variables)
      if (other.name.rfind(base, 0) == 0) ++same;
    v.name = same == 0 ? base : base + std::to_string(same + 1);
    APPRENTICE_CHECK(rule_.variables.size() < kMaxRuleVariables);
    rule_.variables.push_back(std::move(v));
    auto id = static_cast<VariableId>(rule_.variables.size() - 1);
    ids_.emplace(object, id);
    return id;
  }

  LiteralPattern pattern(const Literal& l) {
    LiteralPattern p;
    p.positive = l.positive;
    p.atom.predicate = l.fact.predicate;
    p.atom.arity = static_cast<std::uint8_t>(l.fact.arity);
    for (std::uint16_t i = 0; i < l.fact.arity; ++i) p.atom.args[i] = variable_of(l.fact.args[i]);
    return p;
  }

  const Universe& universe_;
  const Episode& episode_;
  Generalization generalization_;
  Rule rule_;
  std::map<ObjectId, VariableId> ids_;
};

}  // namespace

std::vector<Rule> learn_policy_rules(const Domain& domain, const Universe& universe,
                                     const Episode& episode, Generalization generalization) {
  APPRENTICE_CHECK(episode.sources.size() == episode.actions.size());
  // Replaying checks the episode is what the contract says.
  std::vector<State> states{episode.initial};  // states[i]: before action i
  for (const Action& a : episode.actions) states.push_back(apply(domain, states.back(), a));
  APPRENTICE_CHECK_MSG(episode.goal.satisfied_by(states.back()), "learning from an episode that missed its goal");

  // Actions that lead back to a state already visited (open and close the
  // dishwasher, pick an item up and put it back) are a loop: they achieved
  // nothing, though regression alone would see each undoing the other's
  // effect as a contribution. Only the actions outside loops are analysed.
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < episode.actions.size();) {
    std::size_t next = i;
    for (std::size_t j = episode.actions.size(); j > i; --j) {
      if (states[j] == states[i]) {
        next = j;
        break;
      }
    }
    if (next > i) {
      i = next;
      continue;
    }
    kept.push_back(i++);
  }

  std::set<Literal> needed(episode.goal.literals.begin(), episode.goal.literals.end());
  std::vector<Rule> rules;
  Variablizer variablizer(universe, episode, generalization);
  int steps = 0;
  for (std::size_t k = kept.size(); k-- > 0;) {
    const std::size_t i = kept[k];
    const Action& action = episode.actions[i];
    std::vector<Fact> adds = add_effects_of(domain, action);
    std::vector<Fact> deletes = delete_effects_of(domain, action);
    bool contributes = std::any_of(needed.begin(), needed.end(), [&](const Literal& l) {
      return l.positive ? contains(adds, l.fact) : contains(deletes, l.fact);
    });
    if (!contributes) continue;
    std::set<Literal> before;
    for (const Literal& l : needed) {
      bool achieved_here = l.positive ? contains(adds, l.fact) : contains(deletes, l.fact);
      if (!achieved_here) before.insert(l);
    }
    for (const Literal& p : preconditions_of(domain, action)) before.insert(p);
    ++steps;
    rules.push_back(variablizer.make_rule(domain, before, action, steps, episode.sources[i]));
    needed = std::move(before);
  }
  return rules;
}

}  // namespace apprentice
