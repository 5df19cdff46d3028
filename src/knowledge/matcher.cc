#include "knowledge/matcher.h"

#include <algorithm>
#include <array>
#include <set>
#include <tuple>

namespace apprentice {

namespace {

constexpr ObjectId kUnbound = static_cast<ObjectId>(-1);

std::string shape_of(const std::vector<std::pair<PredicateId, bool>>& parts) {
  std::vector<std::pair<PredicateId, bool>> sorted = parts;
  std::sort(sorted.begin(), sorted.end());
  std::string key;
  for (auto [p, positive] : sorted) key += std::to_string(p) + (positive ? "+" : "-") + ",";
  return key;
}

// Backtracking unification of a rule against the goal and the state. One
// unifier serves all the rules of a query, reusing its buffers, so that
// trying a rule allocates nothing.
class Unifier {
  // The variables one atom bound: at most its arity.
  struct Newly {
    std::array<VariableId, kMaxArity> variables{};
    std::uint8_t count = 0;
  };

 public:
  Unifier(const Universe& universe, const MatchQuery& query) : universe_(universe), query_(query) {}

  // Calls found(binding) for every full match of `rule`.
  template <typename Found>
  void run(const Rule& rule, Found found) {
    if (rule.goal.size() != query_.goal->literals.size()) return;
    rule_ = &rule;
    binding_.fill(kUnbound);
    order_.clear();
    for (std::size_t i = 0; i < rule.conditions.size(); ++i)
      if (rule.conditions[i].positive) order_.push_back(i);
    for (std::size_t i = 0; i < rule.conditions.size(); ++i)
      if (!rule.conditions[i].positive) order_.push_back(i);
    used_goal_.assign(rule.goal.size(), false);
    match_goal(0, found);
  }

 private:
  // Variables bind distinct objects; a rule has at most kMaxRuleVariables,
  // so a scan of the bindings is cheaper than a set.
  bool is_bound(ObjectId o) const {
    for (std::size_t v = 0; v < rule_->variables.size(); ++v)
      if (binding_[v] == o) return true;
    return false;
  }

  bool bind(const AtomPattern& pattern, const Fact& fact, Newly& newly) {
    if (pattern.predicate != fact.predicate || pattern.arity != fact.arity) return false;
    for (std::uint8_t i = 0; i < pattern.arity; ++i) {
      VariableId v = pattern.args[i];
      ObjectId o = fact.args[i];
      if (binding_[v] == o) continue;
      if (binding_[v] != kUnbound || is_bound(o) || !admissible(v, o)) {
        unbind(newly);
        return false;
      }
      binding_[v] = o;
      newly.variables[newly.count++] = v;
    }
    return true;
  }

  void unbind(Newly& newly) {
    for (std::uint8_t i = 0; i < newly.count; ++i) binding_[newly.variables[i]] = kUnbound;
    newly.count = 0;
  }

  bool admissible(VariableId v, ObjectId o) const {
    const RuleVariable& variable = rule_->variables[v];
    if (variable.object_of_interest && o != query_.object_of_interest) return false;
    if (!variable.object_of_interest && o == query_.object_of_interest) return false;
    if (variable.category && universe_.info(o).category != *variable.category) return false;
    return true;
  }

  template <typename Found>
  void match_goal(std::size_t j, Found& found) {
    if (j == rule_->goal.size()) {
      match_conditions(0, found);
      return;
    }
    const LiteralPattern& pattern = rule_->goal[j];
    for (std::size_t k = 0; k < query_.goal->literals.size(); ++k) {
      const Literal& literal = query_.goal->literals[k];
      if (used_goal_[k] || literal.positive != pattern.positive) continue;
      Newly newly;
      if (!bind(pattern.atom, literal.fact, newly)) continue;
      used_goal_[k] = true;
      match_goal(j + 1, found);
      used_goal_[k] = false;
      unbind(newly);
    }
  }

  bool fully_bound(const AtomPattern& atom) const {
    for (std::uint8_t i = 0; i < atom.arity; ++i)
      if (binding_[atom.args[i]] == kUnbound) return false;
    return true;
  }

  Fact ground(const AtomPattern& atom) const {
    Fact f;
    f.predicate = atom.predicate;
    for (std::uint8_t i = 0; i < atom.arity; ++i) f.args[f.arity++] = binding_[atom.args[i]];
    return f;
  }

  template <typename Found>
  void match_conditions(std::size_t j, Found& found) {
    // Conditions run in order_: positive ones first, so that a negative
    // condition is only tested once the positive ones bound its variables.
    // Bound conditions are checked directly; the first with free variables
    // enumerates the state's facts of its predicate.
    for (; j < order_.size(); ++j) {
      const LiteralPattern& c = rule_->conditions[order_[j]];
      if (!fully_bound(c.atom)) break;
      if (query_.state->holds(ground(c.atom)) != c.positive) return;
    }
    if (j == order_.size()) {
      found(binding_);
      return;
    }
    const LiteralPattern& c = rule_->conditions[order_[j]];
    // A negative condition whose variables nothing binds cannot be decided:
    // the rule does not match. Learned rules never contain one.
    if (!c.positive) return;
    // Facts of the condition's predicate, in the state's order; only those
    // about its first argument when that is known (O(log n) to find).
    // (An unbound variable for the object of interest can only take that.)
    ObjectId first = c.atom.arity > 0 ? binding_[c.atom.args[0]] : kUnbound;
    if (first == kUnbound && c.atom.arity > 0 && rule_->variables[c.atom.args[0]].object_of_interest)
      first = query_.object_of_interest;
    const FactRange facts = first != kUnbound ? query_.state->facts_of(c.atom.predicate, c.atom.arity, first)
                                              : query_.state->facts_of(c.atom.predicate);
    for (const Fact& fact : facts) {
      Newly newly;
      if (!bind(c.atom, fact, newly)) continue;
      match_conditions(j + 1, found);
      unbind(newly);
    }
  }

  const Universe& universe_;
  const MatchQuery& query_;
  const Rule* rule_ = nullptr;
  std::array<ObjectId, kMaxRuleVariables> binding_{};
  std::vector<bool> used_goal_;
  std::vector<std::size_t> order_;
};

// The category a rule's goal pattern tests first, or "*".
std::string goal_category(const Rule& rule) {
  for (const LiteralPattern& l : rule.goal)
    for (std::uint8_t i = 0; i < l.atom.arity; ++i)
      if (rule.variables[l.atom.args[i]].category) return *rule.variables[l.atom.args[i]].category;
  return "*";
}

}  // namespace

std::string RuleMatcher::goal_shape(const std::vector<Literal>& goal) {
  std::vector<std::pair<PredicateId, bool>> parts;
  for (const Literal& l : goal) parts.emplace_back(l.fact.predicate, l.positive);
  return shape_of(parts);
}

std::string RuleMatcher::bucket_key(std::string_view shape, std::string_view category, std::string_view subtask) {
  std::string key(shape);
  key += '|';
  key += category;
  key += '|';
  key += subtask;
  return key;
}

bool RuleMatcher::add(const Domain& domain, Rule rule) {
  std::string signature = rule_signature(domain, rule);
  if (!signatures_.emplace(signature, true).second) return false;
  std::vector<std::pair<PredicateId, bool>> parts;
  for (const LiteralPattern& l : rule.goal) parts.emplace_back(l.atom.predicate, l.positive);
  buckets_[bucket_key(shape_of(parts), goal_category(rule), rule.subtask.value_or(""))].push_back(rules_.size());
  rules_.push_back(std::move(rule));
  return true;
}

std::vector<Proposal> RuleMatcher::propose(const Domain& domain, const Universe& universe,
                                           const MatchQuery& query) const {
  (void)domain;
  // The buckets that can hold a matching rule: this goal's shape; a goal
  // category of "*" or one of the goal's objects' categories; no subtask
  // test or this subtask.
  std::set<std::string> categories{"*"};
  for (ObjectId o : query.goal->objects()) categories.insert(universe.info(o).category);
  std::vector<std::string_view> subtasks{""};
  if (!query.subtask.empty()) subtasks.push_back(query.subtask);
  std::string shape = goal_shape(query.goal->literals);
  std::vector<Proposal> out;
  Unifier unifier(universe, query);
  for (const std::string& category : categories) {
    for (std::string_view subtask : subtasks) {
      auto bucket = buckets_.find(bucket_key(shape, category, subtask));
      if (bucket == buckets_.end()) continue;
      for (std::size_t index : bucket->second) {
        const Rule& rule = rules_[index];
        if (rule.subtask && *rule.subtask != query.subtask) continue;
        unifier.run(rule, [&](const std::array<ObjectId, kMaxRuleVariables>& binding) {
          std::vector<ObjectId> args;
          for (VariableId v : rule.action_args) args.push_back(binding[v]);
          Action action(rule.action, args);
          auto same = std::find_if(out.begin(), out.end(), [&](const Proposal& p) { return p.action == action; });
          if (same == out.end()) {
            out.push_back(Proposal{action, rule.steps_to_goal, index});
          } else if (std::tie(rule.steps_to_goal, index) < std::tie(same->steps_to_goal, same->rule_index)) {
            same->steps_to_goal = rule.steps_to_goal;
            same->rule_index = index;
          }
        });
      }
    }
  }
  // One rule may propose several actions: ties go to the smaller action, so
  // that the order never depends on the order the buckets were read in.
  std::sort(out.begin(), out.end(), [](const Proposal& a, const Proposal& b) {
    return std::tie(a.steps_to_goal, a.rule_index, a.action) < std::tie(b.steps_to_goal, b.rule_index, b.action);
  });
  return out;
}

std::optional<Proposal> RuleMatcher::select(const Domain& domain, const Universe& universe,
                                            const MatchQuery& query) const {
  auto proposals = propose(domain, universe, query);
  if (proposals.empty()) return std::nullopt;
  return proposals.front();
}

}  // namespace apprentice
