#include "world/action.h"

#include <algorithm>

#include "world/goal.h"
#include "world/goal_reader.h"
#include "world/sexpr.h"

namespace apprentice {

Action::Action(ActionSchemaId s, std::span<const ObjectId> arguments) : schema(s) {
  APPRENTICE_CHECK(arguments.size() <= kMaxParameters);
  for (ObjectId a : arguments) args[arity++] = a;
}

Fact instantiate(const AtomSchema& atom, const Action& action) {
  Fact fact;
  fact.predicate = atom.predicate;
  for (std::uint8_t p : atom.parameters) fact.args[fact.arity++] = action.args[p];
  return fact;
}

std::vector<Literal> preconditions_of(const Domain& domain, const Action& action) {
  std::vector<Literal> out;
  for (const LiteralSchema& l : domain.actions.at(action.schema).preconditions)
    out.push_back(Literal{instantiate(l.atom, action), l.positive});
  return out;
}

std::vector<Fact> add_effects_of(const Domain& domain, const Action& action) {
  std::vector<Fact> out;
  for (const AtomSchema& a : domain.actions.at(action.schema).add_effects)
    out.push_back(instantiate(a, action));
  return out;
}

std::vector<Fact> delete_effects_of(const Domain& domain, const Action& action) {
  std::vector<Fact> out;
  for (const AtomSchema& a : domain.actions.at(action.schema).delete_effects)
    out.push_back(instantiate(a, action));
  return out;
}

std::optional<std::string> why_not_applicable(const Domain& domain, const Universe& universe,
                                              const State& state, const Action& action) {
  const ActionSchema& schema = domain.actions.at(action.schema);
  if (action.arity != schema.parameters.size())
    return schema.name + " takes " + std::to_string(schema.parameters.size()) + " arguments";
  for (std::size_t i = 0; i < action.arity; ++i) {
    TypeId type = universe.info(action.args[i]).type;
    if (!domain.is_subtype(type, schema.parameters[i].type))
      return universe.name(action.args[i]) + " is not a " + type_word(domain, schema.parameters[i].type);
  }
  for (const EqualitySchema& e : schema.equalities) {
    bool equal = action.args[e.left] == action.args[e.right];
    if (equal != e.positive)
      return universe.name(action.args[e.left]) + (e.positive ? " differs from " : " is the same as ") +
             universe.name(action.args[e.right]);
  }
  for (const LiteralSchema& l : schema.preconditions) {
    Fact fact = instantiate(l.atom, action);
    if (state.holds(fact) != l.positive)
      return format_fact(domain, universe, fact) + (l.positive ? " is false" : " is true");
  }
  return std::nullopt;
}

bool is_applicable(const Domain& domain, const State& state, const Action& action) {
  const ActionSchema& schema = domain.actions[action.schema];
  for (const EqualitySchema& e : schema.equalities)
    if ((action.args[e.left] == action.args[e.right]) != e.positive) return false;
  for (const LiteralSchema& l : schema.preconditions)
    if (state.holds(instantiate(l.atom, action)) != l.positive) return false;
  return true;
}

State apply(const Domain& domain, const State& state, const Action& action) {
  APPRENTICE_CHECK(is_applicable(domain, state, action));
  return state.with_changes(delete_effects_of(domain, action), add_effects_of(domain, action));
}

std::string format_action(const Domain& domain, const Universe& universe, const Action& action) {
  std::string out = "(" + domain.actions.at(action.schema).name;
  for (ObjectId o : action.arguments()) out += " " + universe.name(o);
  return out + ")";
}

Result<Action> parse_action(const Domain& domain, const Universe& universe, std::string_view text) {
  auto expr = parse_sexpr(text, "action");
  if (!expr) return tl::unexpected(expr.error());
  if (!expr->is_list || expr->items.empty() || expr->items[0].is_list)
    return tl::unexpected(syntax_error("action", expr->position, "expected an action such as (open fridge1)"));
  auto schema_id = domain.find_action(expr->items[0].atom);
  if (!schema_id)
    return tl::unexpected(syntax_error("action", expr->items[0].position,
                                       "expected an action of domain " + domain.name + ", not " +
                                           expr->items[0].atom));
  const ActionSchema& schema = domain.actions[*schema_id];
  if (expr->items.size() - 1 != schema.parameters.size())
    return tl::unexpected(syntax_error("action", expr->position,
                                       "expected " + std::to_string(schema.parameters.size()) +
                                           " arguments for " + schema.name));
  std::vector<ObjectId> args;
  for (std::size_t i = 1; i < expr->items.size(); ++i) {
    const SExpr& term = expr->items[i];
    auto object = term.is_list ? std::nullopt : universe.find(term.atom);
    if (!object)
      return tl::unexpected(syntax_error("action", term.position,
                                         term.is_list ? "expected an object; there is no list"
                                                      : no_such_object(universe, term.atom)));
    if (!domain.is_subtype(universe.info(*object).type, schema.parameters[i - 1].type))
      return tl::unexpected(syntax_error("action", term.position,
                                         "expected a " + type_word(domain, schema.parameters[i - 1].type) +
                                             "; " + term.atom + " is not one"));
    args.push_back(*object);
  }
  return Action(*schema_id, args);
}

namespace {

// Depth-first enumeration of argument tuples, pruning on types and on
// static preconditions as soon as their parameters are bound.
class Grounder {
 public:
  Grounder(const Domain& domain, const Universe& universe, std::span<const ObjectId> objects,
           const State& state, std::vector<Action>& out)
      : domain_(domain), universe_(universe), objects_(objects), state_(state), out_(out) {}

  void ground(ActionSchemaId id) {
    schema_id_ = id;
    const ActionSchema& schema = domain_.actions[id];
    candidates_.assign(schema.parameters.size(), {});
    for (std::size_t p = 0; p < schema.parameters.size(); ++p)
      for (ObjectId o : objects_)
        if (domain_.is_subtype(universe_.info(o).type, schema.parameters[p].type))
          candidates_[p].push_back(o);
    current_ = Action();
    current_.schema = id;
    current_.arity = static_cast<std::uint8_t>(schema.parameters.size());
    extend(0);
  }

 private:
  void extend(std::size_t p) {
    const ActionSchema& schema = domain_.actions[schema_id_];
    if (p == schema.parameters.size()) {
      out_.push_back(current_);
      return;
    }
    for (ObjectId o : candidates_[p]) {
      current_.args[p] = o;
      if (consistent_up_to(p)) extend(p + 1);
    }
  }

  // Checks the constraints whose parameters are all among 0..p and that
  // mention p: equalities, and preconditions on static predicates.
  bool consistent_up_to(std::size_t p) const {
    const ActionSchema& schema = domain_.actions[schema_id_];
    for (const EqualitySchema& e : schema.equalities) {
      if (std::max(e.left, e.right) != p) continue;
      if ((current_.args[e.left] == current_.args[e.right]) != e.positive) return false;
    }
    for (const LiteralSchema& l : schema.preconditions) {
      if (!domain_.is_static(l.atom.predicate)) continue;
      std::uint8_t highest = 0;
      for (std::uint8_t q : l.atom.parameters) highest = std::max(highest, q);
      if (l.atom.parameters.empty() ? p != 0 : highest != p) continue;
      if (state_.holds(instantiate(l.atom, current_)) != l.positive) return false;
    }
    return true;
  }

  const Domain& domain_;
  const Universe& universe_;
  std::span<const ObjectId> objects_;
  const State& state_;
  std::vector<Action>& out_;
  ActionSchemaId schema_id_ = 0;
  std::vector<std::vector<ObjectId>> candidates_;
  Action current_;
};

}  // namespace

std::vector<Action> ground_actions(const Domain& domain, const Universe& universe,
                                   std::span<const ObjectId> objects, const State& state) {
  std::vector<ObjectId> sorted(objects.begin(), objects.end());
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<Action> out;
  Grounder grounder(domain, universe, sorted, state, out);
  for (std::size_t id = 0; id < domain.actions.size(); ++id) {
    if (domain.actions[id].parameters.empty()) {
      // A parameterless action has one grounding; check its static preconditions.
      Action a;
      a.schema = static_cast<ActionSchemaId>(id);
      bool ok = true;
      for (const LiteralSchema& l : domain.actions[id].preconditions)
        if (domain.is_static(l.atom.predicate) && state.holds(instantiate(l.atom, a)) != l.positive) ok = false;
      if (ok) out.push_back(a);
      continue;
    }
    grounder.ground(static_cast<ActionSchemaId>(id));
  }
  return out;
}

}  // namespace apprentice
