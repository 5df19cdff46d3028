#include "world/state_lookup.h"

#include <algorithm>

namespace apprentice {

std::span<const Fact> facts_about(const State& state, PredicateId predicate, ObjectId first) {
  const std::span<const Fact> facts = state.facts();
  const Fact lowest(predicate, {first, ObjectId{0}});
  auto begin = std::lower_bound(facts.begin(), facts.end(), lowest);
  auto end = begin;
  while (end != facts.end() && end->predicate == predicate && end->arity == 2 && end->args[0] == first) ++end;
  return {begin, end};
}

}  // namespace apprentice
