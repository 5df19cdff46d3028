// Learned policy knowledge: rules that propose an action when the current
// goal and state match, in the spirit of the paper's Soar chunks.
//
// A rule's variables stand for objects. The goal pattern must match the
// agent's whole current goal; the state conditions must then hold in the
// current state, binding any variables the goal left free (the surface the
// object is on, say). A rule that matches proposes its action; among
// several, the agent selects the one with the fewest steps left to the goal.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "world/domain.h"
#include "world/fact.h"
#include "world/universe.h"

namespace apprentice {

using VariableId = std::uint8_t;
inline constexpr std::size_t kMaxRuleVariables = 16;

struct AtomPattern {
  PredicateId predicate = 0;
  std::uint8_t arity = 0;
  std::array<VariableId, kMaxArity> args{};

  friend auto operator<=>(const AtomPattern&, const AtomPattern&) = default;
  friend bool operator==(const AtomPattern&, const AtomPattern&) = default;
};

struct LiteralPattern {
  AtomPattern atom;
  bool positive = true;

  friend auto operator<=>(const LiteralPattern&, const LiteralPattern&) = default;
  friend bool operator==(const LiteralPattern&, const LiteralPattern&) = default;
};

struct RuleVariable {
  std::string name;                     // "?o", "?r", "?s"
  std::optional<std::string> category;  // a category test, where one is needed
  bool object_of_interest = false;      // bound to the object the subtask is about
  friend bool operator==(const RuleVariable&, const RuleVariable&) = default;
};

// Where a piece of knowledge came from, for `apprentice knowledge`.
struct Provenance {
  std::string object;  // the object it was learned on: "ceramic-plate1 (ceramic-plate)"
  std::string source;  // "instructor: \"Open the fridge.\"", "search", "llm: ..."
  friend bool operator==(const Provenance&, const Provenance&) = default;
};

struct Rule {
  std::vector<RuleVariable> variables;
  std::optional<std::string> subtask;  // a subtask test, where one is needed
  std::vector<LiteralPattern> goal;    // must match the whole current goal
  std::vector<LiteralPattern> conditions;  // must hold in the state
  ActionSchemaId action = 0;
  std::vector<VariableId> action_args;
  int steps_to_goal = 1;  // this action reaches the goal in so many steps
  Provenance provenance;

  friend bool operator==(const Rule&, const Rule&) = default;
};

// The paper's If/Then style:
//   If the goal is {?o in ?r, ?r closed}
//   and ?r is closed, ?r is openable, the hand is empty, ...
//   Then: propose open(?r)   [2 steps... ]
std::string format_rule(const Domain& domain, const Rule& rule);

// A compact one-line form used for golden files and deduplication:
// "open(?r) <- goal{(in ?o ?r) (closed ?r)} state{(closed ?r) ...} steps=4"
std::string rule_signature(const Domain& domain, const Rule& rule);

}  // namespace apprentice
