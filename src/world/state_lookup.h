// Looking facts up in a State without scanning it: facts are sorted by
// predicate, arity and then arguments, so the facts of one predicate about
// one object are neighbours, found by descending the state's tree.
#pragma once

#include <initializer_list>
#include <optional>

#include "world/fact.h"
#include "world/state.h"

namespace apprentice {

// The facts of the arity-2 `predicate` whose first argument is `first`, such
// as every (in mug1 ?place): O(log n) in the state's size.
FactRange facts_about(const State& state, PredicateId predicate, ObjectId first);

// The smallest first fact of several ranges (the one a scan of the whole
// state in order would meet first), or nothing if all are empty.
std::optional<Fact> first_fact(std::initializer_list<FactRange> ranges);

}  // namespace apprentice
