#include "search/relevance.h"

#include <algorithm>

namespace apprentice {

std::vector<ObjectId> relevant_objects(const Domain& domain, const Universe& universe,
                                       const State& state, const Goal& goal) {
  std::vector<bool> relevant(universe.size(), false);
  for (ObjectId o : goal.objects()) relevant[o] = true;
  for (std::size_t o = 0; o < universe.size(); ++o)
    if (universe.info(static_cast<ObjectId>(o)).kind != ObjectKind::kItem) relevant[o] = true;
  for (const Fact& fact : state.facts())
    if (fact.arity == 1 && !domain.is_static(fact.predicate)) relevant[fact.args[0]] = true;
  std::vector<ObjectId> out;
  for (std::size_t o = 0; o < relevant.size(); ++o)
    if (relevant[o]) out.push_back(static_cast<ObjectId>(o));
  return out;
}

State project_state(const State& state, const std::vector<ObjectId>& objects) {
  std::vector<Fact> kept;
  for (const Fact& fact : state.facts()) {
    bool all_in = true;
    for (ObjectId o : fact.arguments())
      if (!std::binary_search(objects.begin(), objects.end(), o)) all_in = false;
    if (all_in) kept.push_back(fact);
  }
  return State(std::move(kept));
}

}  // namespace apprentice
