// Ground actions: an action schema of the domain with objects for its
// parameters, such as (open fridge1) or (put-in ketchup1 fridge1).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"
#include "world/domain.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

struct Action {
  ActionSchemaId schema = 0;
  std::uint8_t arity = 0;
  std::array<ObjectId, kMaxParameters> args{};

  Action() = default;
  Action(ActionSchemaId s, std::span<const ObjectId> arguments);

  std::span<const ObjectId> arguments() const { return {args.data(), arity}; }

  friend auto operator<=>(const Action&, const Action&) = default;
  friend bool operator==(const Action&, const Action&) = default;
};

// Why an action cannot be applied, or nullopt if it can: "(handempty) is
// false", "(closed fridge1) is true". Type errors count too.
std::optional<std::string> why_not_applicable(const Domain& domain, const Universe& universe,
                                              const State& state, const Action& action);
bool is_applicable(const Domain& domain, const State& state, const Action& action);

// The successor state. The action must be applicable (checked).
State apply(const Domain& domain, const State& state, const Action& action);

// An atom of the action's schema with the action's arguments: (in ?o ?r)
// of (put-in ketchup1 fridge1) is (in ketchup1 fridge1).
Fact instantiate(const AtomSchema& atom, const Action& action);

// The instantiated preconditions and effects of an action.
std::vector<Literal> preconditions_of(const Domain& domain, const Action& action);
std::vector<Fact> add_effects_of(const Domain& domain, const Action& action);
std::vector<Fact> delete_effects_of(const Domain& domain, const Action& action);

// "(put-in ketchup1 fridge1)"
std::string format_action(const Domain& domain, const Universe& universe, const Action& action);
// Parses "(open fridge1)", checking the action name, arity and parameter types.
Result<Action> parse_action(const Domain& domain, const Universe& universe, std::string_view text);

// Every ground action over `objects` whose parameter types fit and whose
// static preconditions hold in `state`, in a deterministic order (by schema,
// then by argument ids). Equality constraints are applied too.
std::vector<Action> ground_actions(const Domain& domain, const Universe& universe,
                                   std::span<const ObjectId> objects, const State& state);

}  // namespace apprentice
