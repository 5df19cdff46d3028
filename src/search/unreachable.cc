#include "search/unreachable.h"

#include <algorithm>
#include <optional>

#include "search/ground_task.h"
#include "search/relevance.h"
#include "world/action.h"

namespace apprentice {
namespace {

constexpr std::size_t kMaxChain = 4;

// What the planners' relaxed reachability says about single literals.
class Reachability {
 public:
  Reachability(const Domain& domain, const Universe& universe, const State& state, const Goal& goal)
      : domain_(domain),
        universe_(universe),
        scope_(search_scope(domain, universe, state, goal, /*prune=*/true)),
        task_(domain, universe, scope_.objects, scope_.state, goal),
        added_(task_.proposition_count(), false),
        deleted_(task_.proposition_count(), false) {
    for (OperatorId o = 0; o < task_.operator_count(); ++o) {
      for (PropositionId p : task_.list(task_.op(o).adds)) added_[p] = true;
      for (PropositionId p : task_.list(task_.op(o).deletes)) deleted_[p] = true;
    }
  }

  // Whether some sequence of actions could make `literal` hold, ignoring
  // what else the actions undo.
  bool can_hold(const Literal& literal) const {
    const bool now = scope_.state.holds(literal.fact);
    if (now == literal.positive) return true;
    if (domain_.is_static(literal.fact.predicate)) return false;
    auto p = proposition(literal.fact);
    // A fact no enabled action touches keeps its value.
    if (!p) return false;
    return literal.positive ? added_[*p] : deleted_[*p];
  }

  UnreachableLiteral explain(const Literal& literal) const {
    UnreachableLiteral out{literal, UnreachableLiteral::Reason::kNoAction, {}};
    for (ActionSchemaId a = 0; a < domain_.actions.size(); ++a) {
      const ActionSchema& schema = domain_.actions[a];
      for (const AtomSchema& effect : literal.positive ? schema.add_effects : schema.delete_effects) {
        if (effect.predicate != literal.fact.predicate || effect.parameters.size() != literal.fact.arity) continue;
        if (auto blocker = why_not(a, effect, literal)) out.blockers.push_back(std::move(*blocker));
      }
    }
    if (!out.blockers.empty()) out.reason = UnreachableLiteral::Reason::kNoActionApplies;
    return out;
  }

 private:
  std::optional<PropositionId> proposition(const Fact& f) const {
    PropositionId lo = 0, hi = static_cast<PropositionId>(task_.proposition_count());
    while (lo < hi) {
      PropositionId mid = lo + (hi - lo) / 2;
      if (task_.fact(mid) < f) lo = mid + 1; else hi = mid;
    }
    if (lo < task_.proposition_count() && task_.fact(lo) == f) return lo;
    return std::nullopt;
  }

  // Why action schema `a`, whose `effect` would make `literal` hold, cannot
  // here; nullopt if the effect cannot produce this fact at all (it would
  // need one parameter to be two objects, or breaks an equality).
  std::optional<UnreachableBlocker> why_not(ActionSchemaId a, const AtomSchema& effect, const Literal& literal) const {
    const ActionSchema& schema = domain_.actions[a];
    std::vector<std::optional<ObjectId>> binding(schema.parameters.size());
    for (std::size_t i = 0; i < effect.parameters.size(); ++i) {
      std::optional<ObjectId>& slot = binding[effect.parameters[i]];
      if (slot && *slot != literal.fact.args[i]) return std::nullopt;
      slot = literal.fact.args[i];
    }
    for (const EqualitySchema& e : schema.equalities)
      if (binding[e.left] && binding[e.right] && (*binding[e.left] == *binding[e.right]) != e.positive)
        return std::nullopt;

    UnreachableBlocker blocker;
    blocker.schema = a;
    if (std::all_of(binding.begin(), binding.end(), [](const auto& b) { return b.has_value(); })) {
      std::vector<ObjectId> args;
      for (const auto& b : binding) args.push_back(*b);
      blocker.action = Action(a, args);
    }
    for (std::size_t p = 0; p < binding.size(); ++p) {
      if (binding[p] && !domain_.is_subtype(universe_.info(*binding[p]).type, schema.parameters[p].type)) {
        blocker.kind = UnreachableBlocker::Kind::kWrongType;
        blocker.object = *binding[p];
        blocker.type = schema.parameters[p].type;
        return blocker;
      }
    }
    for (const LiteralSchema& pre : schema.preconditions) {
      if (!domain_.is_static(pre.atom.predicate)) continue;
      Fact f;
      f.predicate = pre.atom.predicate;
      bool bound = true;
      for (std::uint8_t parameter : pre.atom.parameters) {
        if (!binding[parameter]) bound = false;
        else f.args[f.arity++] = *binding[parameter];
      }
      if (bound && scope_.state.holds(f) != pre.positive) {
        blocker.kind = UnreachableBlocker::Kind::kStaticPrecondition;
        blocker.precondition = Literal{f, pre.positive};
        return blocker;
      }
    }
    // The ground actions that fit the binding: each has a precondition
    // that can never hold, or it would make the literal hold.
    for (const Action& action : ground()) {
      if (action.schema != a) continue;
      bool fits = true;
      for (std::size_t p = 0; p < binding.size(); ++p) fits = fits && (!binding[p] || *binding[p] == action.args[p]);
      if (!fits) continue;
      for (const Literal& pre : preconditions_of(domain_, action)) {
        if (!pre.positive || can_hold(pre)) continue;
        blocker.kind = UnreachableBlocker::Kind::kPreconditionNeverHolds;
        blocker.precondition = pre;
        return blocker;
      }
    }
    blocker.kind = UnreachableBlocker::Kind::kNoObjectFits;
    return blocker;
  }

  const std::vector<Action>& ground() const {
    if (!ground_) ground_ = ground_actions(domain_, universe_, scope_.objects, scope_.state);
    return *ground_;
  }

  const Domain& domain_;
  const Universe& universe_;
  SearchScope scope_;
  GroundTask task_;
  std::vector<bool> added_, deleted_;
  mutable std::optional<std::vector<Action>> ground_;
};

}  // namespace

UnreachableChain explain_unreachable(const Domain& domain, const Universe& universe, const State& state,
                                     const Goal& goal) {
  Reachability reachability(domain, universe, state, goal);
  UnreachableChain chain;
  for (const Literal& l : goal.literals) {
    if (reachability.can_hold(l)) continue;
    chain.push_back(reachability.explain(l));
    break;
  }
  while (!chain.empty() && chain.size() < kMaxChain) {
    const auto& blockers = chain.back().blockers;
    auto next = std::find_if(blockers.begin(), blockers.end(), [](const UnreachableBlocker& b) {
      return b.kind == UnreachableBlocker::Kind::kPreconditionNeverHolds;
    });
    if (next == blockers.end()) break;
    const Literal precondition = next->precondition;
    if (std::any_of(chain.begin(), chain.end(), [&](const UnreachableLiteral& u) { return u.literal == precondition; }))
      break;
    chain.push_back(reachability.explain(precondition));
  }
  return chain;
}

}  // namespace apprentice
