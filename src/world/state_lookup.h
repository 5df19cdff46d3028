// Looking facts up in a State without scanning it: facts are sorted by
// predicate, arity and then arguments, so the facts of one predicate about
// one object are neighbours, found by binary search.
#pragma once

#include <span>

#include "world/fact.h"
#include "world/state.h"

namespace apprentice {

// The facts of the arity-2 `predicate` whose first argument is `first`, such
// as every (in mug1 ?place): O(log n) in the state's size.
std::span<const Fact> facts_about(const State& state, PredicateId predicate, ObjectId first);

}  // namespace apprentice
