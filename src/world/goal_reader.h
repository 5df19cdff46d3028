// Internal to the world module: reading ground atoms and goals from
// already-parsed s-expressions (shared by parse_goal and the problem reader).
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/sexpr.h"
#include "world/universe.h"

namespace apprentice {

// (p a b) with object names; checks the predicate, arity and types.
Result<Fact> fact_from_sexpr(const Domain& domain, const Universe& universe, const SExpr& expr,
                             std::string_view source);
// (and L...) or L, where L is a fact or (not fact).
Result<Goal> goal_from_sexpr(const Domain& domain, const Universe& universe, const SExpr& expr,
                             std::string_view source);

// "expected an object; there is no ketchup; did you mean ketchup1?"
std::string no_such_object(const Universe& universe, std::string_view name);

}  // namespace apprentice
