// Whether each literal of a goal can ever hold from a state and, for one
// that cannot, why: read off the action model, for `apprentice plan` to say
// in English (language/narration.h) instead of only "exhausted".
//
// "Can ever hold" is the planners' own relaxed reachability (GroundTask:
// every action that can fire when deletes are ignored, over the objects
// relevance analysis keeps), so a literal reported here is one no plan of
// any length reaches. The reasons are then found per action that could make
// the literal hold (an add effect with its predicate; a delete effect for a
// negative literal): the literal's objects are of the wrong type for it; a
// static precondition, such as (openable ?r), is not so for them; no
// objects here fit its other static preconditions; or one of its
// preconditions can never hold either, which is explained in turn.
#pragma once

#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"
#include "world/unreachable.h"

namespace apprentice {

// The first literal of `goal` (in its order) that can never hold from
// `state`, why, and why for the precondition that blocks it, and so on (at
// most four links). Empty when each literal can hold on its own.
UnreachableChain explain_unreachable(const Domain& domain, const Universe& universe, const State& state,
                                     const Goal& goal);

}  // namespace apprentice
