#include "world/domain.h"

#include "util/check.h"

namespace apprentice {

Domain::Domain() { types.push_back(TypeInfo{"object", kRootType}); }

std::optional<TypeId> Domain::find_type(std::string_view type_name) const {
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i].name == type_name) return static_cast<TypeId>(i);
  return std::nullopt;
}

std::optional<PredicateId> Domain::find_predicate(std::string_view predicate_name) const {
  for (std::size_t i = 0; i < predicates.size(); ++i)
    if (predicates[i].name == predicate_name) return static_cast<PredicateId>(i);
  return std::nullopt;
}

std::optional<ActionSchemaId> Domain::find_action(std::string_view action_name) const {
  for (std::size_t i = 0; i < actions.size(); ++i)
    if (actions[i].name == action_name) return static_cast<ActionSchemaId>(i);
  return std::nullopt;
}

PredicateId Domain::predicate(std::string_view predicate_name) const {
  auto found = find_predicate(predicate_name);
  APPRENTICE_CHECK_MSG(found.has_value(), "the domain lacks a predicate the program relies on");
  return *found;
}

bool Domain::is_subtype(TypeId type, TypeId ancestor) const {
  for (;;) {
    if (type == ancestor) return true;
    if (type == kRootType) return false;
    type = types[type].parent;
  }
}

bool Domain::is_static(PredicateId p) const {
  APPRENTICE_CHECK(p < static_predicates.size());
  return static_predicates[p];
}

}  // namespace apprentice
