// The action model: a STRIPS domain with typing, negative preconditions and
// equality, as read from a PDDL file by world/pddl_reader.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "world/fact.h"

namespace apprentice {

using TypeId = std::uint16_t;
using ActionSchemaId = std::uint16_t;

inline constexpr TypeId kRootType = 0;  // PDDL's "object"
inline constexpr std::size_t kMaxParameters = 6;

struct TypeInfo {
  std::string name;
  TypeId parent = kRootType;  // the root is its own parent
};

struct PredicateSchema {
  std::string name;
  std::vector<TypeId> parameter_types;
};

// An atom inside an action schema; each argument is the index of one of
// the action's parameters.
struct AtomSchema {
  PredicateId predicate = 0;
  std::vector<std::uint8_t> parameters;
};

struct LiteralSchema {
  AtomSchema atom;
  bool positive = true;
};

// (= ?a ?b) or (not (= ?a ?b)) over parameter indices.
struct EqualitySchema {
  std::uint8_t left = 0;
  std::uint8_t right = 0;
  bool positive = true;
};

struct Parameter {
  std::string name;  // with the leading '?'
  TypeId type = kRootType;
};

struct ActionSchema {
  std::string name;
  std::vector<Parameter> parameters;
  std::vector<LiteralSchema> preconditions;
  std::vector<EqualitySchema> equalities;
  std::vector<AtomSchema> add_effects;
  std::vector<AtomSchema> delete_effects;
};

class Domain {
 public:
  std::string name;
  std::vector<std::string> requirements;  // without the leading ':'
  std::vector<TypeInfo> types;            // types[0] is "object"
  std::vector<PredicateSchema> predicates;
  std::vector<ActionSchema> actions;

  Domain();

  std::optional<TypeId> find_type(std::string_view name) const;
  std::optional<PredicateId> find_predicate(std::string_view name) const;
  std::optional<ActionSchemaId> find_action(std::string_view name) const;
  // Like find_predicate, for names the program itself relies on; a missing
  // one is a bug in the domain file's contract, checked at load time.
  PredicateId predicate(std::string_view name) const;

  bool is_subtype(TypeId type, TypeId ancestor) const;
  // True if no action adds or deletes the predicate (an affordance).
  bool is_static(PredicateId predicate) const;

  // Computed by the reader once all actions are known.
  std::vector<bool> static_predicates;
};

}  // namespace apprentice
