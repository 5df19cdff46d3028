// Why a literal of a goal can never hold: what search/unreachable.h finds
// from the action model, and language/narration.h says in English ("The
// garbage will never be closed: it has no door, so I cannot close it.").
#pragma once

#include <optional>
#include <vector>

#include "world/action.h"
#include "world/domain.h"
#include "world/fact.h"

namespace apprentice {

// One action that would make the literal hold, and why it cannot here.
struct UnreachableBlocker {
  enum class Kind {
    kWrongType,              // `object` is not of the parameter's `type`
    kStaticPrecondition,     // `precondition`, which no action changes, is not so: (openable garbage1)
    kNoObjectFits,           // no objects here satisfy its other static preconditions
    kPreconditionNeverHolds, // `precondition` can never hold either
  };
  Kind kind = Kind::kStaticPrecondition;
  ActionSchemaId schema = 0;
  // The action, when the literal names every one of its parameters:
  // (close garbage1) for (closed garbage1).
  std::optional<Action> action;
  ObjectId object = 0;  // kWrongType
  TypeId type = 0;      // kWrongType
  Literal precondition; // kStaticPrecondition, kPreconditionNeverHolds
};

struct UnreachableLiteral {
  enum class Reason {
    kNoAction,         // no action adds the predicate (for a negative literal: deletes it)
    kNoActionApplies,  // some do, and `blockers` says why none can for these objects
  };
  Literal literal;
  Reason reason = Reason::kNoAction;
  std::vector<UnreachableBlocker> blockers;  // kNoActionApplies: one per achieving action effect
};

// [0] is the goal's literal that can never hold; each further element
// explains the precondition named by the previous one's first
// kPreconditionNeverHolds blocker. Empty: every literal of the goal can hold
// on its own (the goal may still be unreachable, its parts in conflict).
using UnreachableChain = std::vector<UnreachableLiteral>;

}  // namespace apprentice
