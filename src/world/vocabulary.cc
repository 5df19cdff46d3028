#include "world/vocabulary.h"

#include <string>

namespace apprentice {

Result<Vocabulary> Vocabulary::resolve(const Domain& domain) {
  Vocabulary v;
  struct Needed {
    const char* name;
    std::size_t arity;
    PredicateId* slot;
  };
  const Needed needed[] = {
      {"on", 2, &v.on},           {"in", 2, &v.in},
      {"holding", 1, &v.holding}, {"handempty", 0, &v.handempty},
      {"closed", 1, &v.closed},   {"grabbable", 1, &v.grabbable},
      {"openable", 1, &v.openable}, {"receptacle", 1, &v.receptacle},
      {"surface", 1, &v.surface},
  };
  for (const Needed& n : needed) {
    auto id = domain.find_predicate(n.name);
    if (!id)
      return make_error(ErrorCode::kInvalidInput, "domain " + domain.name +
                                                      " lacks the predicate (" + n.name + ")");
    if (domain.predicates[*id].parameter_types.size() != n.arity)
      return make_error(ErrorCode::kInvalidInput,
                        "domain " + domain.name + ": predicate " + n.name + " must take " +
                            std::to_string(n.arity) + " arguments");
    *n.slot = *id;
  }
  return v;
}

}  // namespace apprentice
