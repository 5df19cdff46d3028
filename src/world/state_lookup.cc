#include "world/state_lookup.h"

namespace apprentice {

FactRange facts_about(const State& state, PredicateId predicate, ObjectId first) {
  return state.facts_of(predicate, 2, first);
}

std::optional<Fact> first_fact(std::initializer_list<FactRange> ranges) {
  std::optional<Fact> first;
  for (const FactRange& range : ranges)
    if (!range.empty() && (!first || range.front() < *first)) first = range.front();
  return first;
}

}  // namespace apprentice
