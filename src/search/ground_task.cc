#include "search/ground_task.h"

#include <algorithm>

namespace apprentice {
namespace {

// The dynamic preconditions and effects of one ground action, as ranges
// into a shared vector of facts.
struct Instance {
  std::uint32_t requires_true = 0, requires_false = 0, adds = 0, deletes = 0, end = 0;
};

}  // namespace

GroundTask::GroundTask(const Domain& domain, const Universe& universe, std::span<const ObjectId> objects,
                       const State& initial, const Goal& goal) {
  const std::vector<Action> actions = ground_actions(domain, universe, objects, initial);

  // 1. Instantiate the dynamic parts of every action.
  std::vector<Fact> facts;
  std::vector<Instance> instances(actions.size());
  auto push_dynamic = [&](const AtomSchema& atom, const Action& action) {
    if (!domain.is_static(atom.predicate)) facts.push_back(instantiate(atom, action));
  };
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const ActionSchema& schema = domain.actions[actions[i].schema];
    Instance& in = instances[i];
    in.requires_true = static_cast<std::uint32_t>(facts.size());
    for (const LiteralSchema& l : schema.preconditions)
      if (l.positive) push_dynamic(l.atom, actions[i]);
    in.requires_false = static_cast<std::uint32_t>(facts.size());
    for (const LiteralSchema& l : schema.preconditions)
      if (!l.positive) push_dynamic(l.atom, actions[i]);
    in.adds = static_cast<std::uint32_t>(facts.size());
    for (const AtomSchema& a : schema.add_effects) push_dynamic(a, actions[i]);
    in.deletes = static_cast<std::uint32_t>(facts.size());
    for (const AtomSchema& a : schema.delete_effects) push_dynamic(a, actions[i]);
    in.end = static_cast<std::uint32_t>(facts.size());
  }

  // 2. Every dynamic fact mentioned anywhere, sorted, as an index.
  std::vector<Fact> all(facts);
  for (const Literal& l : goal.literals)
    if (!domain.is_static(l.fact.predicate)) all.push_back(l.fact);
  for (const Fact& f : initial.facts())
    if (!domain.is_static(f.predicate)) all.push_back(f);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  auto index_of = [&](const Fact& f) {
    return static_cast<std::uint32_t>(std::lower_bound(all.begin(), all.end(), f) - all.begin());
  };

  // 3. Relaxed reachability: which actions can ever fire when deletes and
  // negative preconditions are ignored. The others are dropped.
  std::vector<std::uint32_t> unmet(actions.size());
  std::vector<std::vector<std::uint32_t>> waiting(all.size());
  std::vector<bool> reached(all.size(), false);
  std::vector<std::uint32_t> queue;
  std::vector<bool> enabled(actions.size(), false);
  for (const Fact& f : initial.facts()) {
    if (domain.is_static(f.predicate)) continue;
    const std::uint32_t i = index_of(f);
    if (!reached[i]) reached[i] = true, queue.push_back(i);
  }
  auto fire = [&](std::size_t a) {
    enabled[a] = true;
    for (std::uint32_t k = instances[a].adds; k < instances[a].deletes; ++k) {
      const std::uint32_t i = index_of(facts[k]);
      if (!reached[i]) reached[i] = true, queue.push_back(i);
    }
  };
  for (std::size_t a = 0; a < actions.size(); ++a) {
    unmet[a] = instances[a].requires_false - instances[a].requires_true;
    for (std::uint32_t k = instances[a].requires_true; k < instances[a].requires_false; ++k)
      waiting[index_of(facts[k])].push_back(static_cast<std::uint32_t>(a));
  }
  for (std::size_t a = 0; a < actions.size(); ++a)
    if (unmet[a] == 0) fire(a);
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (std::uint32_t a : waiting[queue[q]])
      if (--unmet[a] == 0) fire(a);

  // 4. Number the facts the enabled actions and the goal use.
  std::vector<bool> used(all.size(), false);
  for (std::size_t a = 0; a < actions.size(); ++a)
    if (enabled[a])
      for (std::uint32_t k = instances[a].requires_true; k < instances[a].end; ++k) used[index_of(facts[k])] = true;
  for (const Literal& l : goal.literals)
    if (!domain.is_static(l.fact.predicate)) used[index_of(l.fact)] = true;
  std::vector<PropositionId> number(all.size(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!used[i]) continue;
    number[i] = static_cast<PropositionId>(facts_.size());
    facts_.push_back(all[i]);
  }
  words_ = std::max<std::size_t>(1, (facts_.size() + 63) / 64);

  // 5. The operators, the initial state and the goal over those numbers.
  // Each list sorted and without duplicates, appended to flat_.
  auto range = [&](std::uint32_t begin, std::uint32_t end) {
    PropositionRange r;
    r.begin = static_cast<std::uint32_t>(flat_.size());
    for (std::uint32_t k = begin; k < end; ++k) flat_.push_back(number[index_of(facts[k])]);
    std::sort(flat_.begin() + r.begin, flat_.end());
    flat_.erase(std::unique(flat_.begin() + r.begin, flat_.end()), flat_.end());
    r.end = static_cast<std::uint32_t>(flat_.size());
    return r;
  };
  for (std::size_t a = 0; a < actions.size(); ++a) {
    if (!enabled[a]) continue;
    const Instance& in = instances[a];
    GroundOperator op;
    op.action = actions[a];
    op.requires_true = range(in.requires_true, in.requires_false);
    op.requires_false = range(in.requires_false, in.adds);
    op.adds = range(in.adds, in.deletes);
    op.deletes = range(in.deletes, in.end);
    operators_.push_back(op);
  }
  initial_.assign(words_, 0);
  for (const Fact& f : initial.facts()) {
    if (domain.is_static(f.predicate)) continue;
    const std::uint32_t i = index_of(f);
    if (used[i]) set_bit(initial_.data(), number[i]);
  }
  for (const Literal& l : goal.literals) {
    if (domain.is_static(l.fact.predicate)) {
      if (initial.holds(l.fact) != l.positive) goal_statically_false_ = true;
      continue;
    }
    (l.positive ? goal_true_ : goal_false_).push_back(number[index_of(l.fact)]);
  }
}

bool GroundTask::applicable(const StateWord* state, OperatorId id) const {
  const GroundOperator& o = operators_[id];
  for (std::uint32_t k = o.requires_true.begin; k < o.requires_true.end; ++k)
    if (!test_bit(state, flat_[k])) return false;
  for (std::uint32_t k = o.requires_false.begin; k < o.requires_false.end; ++k)
    if (test_bit(state, flat_[k])) return false;
  return true;
}

void GroundTask::apply(const StateWord* state, OperatorId id, StateWord* out) const {
  const GroundOperator& o = operators_[id];
  std::copy(state, state + words_, out);
  for (std::uint32_t k = o.deletes.begin; k < o.deletes.end; ++k) clear_bit(out, flat_[k]);
  for (std::uint32_t k = o.adds.begin; k < o.adds.end; ++k) set_bit(out, flat_[k]);
}

bool GroundTask::is_goal(const StateWord* state) const {
  if (goal_statically_false_) return false;
  for (PropositionId p : goal_true_)
    if (!test_bit(state, p)) return false;
  for (PropositionId p : goal_false_)
    if (test_bit(state, p)) return false;
  return true;
}

}  // namespace apprentice
