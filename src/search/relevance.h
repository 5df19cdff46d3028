// Which objects can matter to a goal. Search grounds and expands actions
// over these objects only, so that a world with thousands of irrelevant
// objects costs no more to plan in than one without them.
#pragma once

#include <vector>

#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

// The relevant objects are: those the goal mentions; every place (surface
// or receptacle), since any of them may have to be opened or used to set
// something down; and every item named in a dynamic one-argument fact (the
// item in hand, which must be put somewhere before the hand is free).
//
// This is exact for domains where items do not interact with each other
// (nothing stacks, nothing fills up), which holds for the kitchen domain:
// an item not in the goal and not in hand never has to move. Domains
// where items interact should plan with relevance pruning off.
//
// Returns sorted ids. Linear in the size of the universe and the state.
std::vector<ObjectId> relevant_objects(const Domain& domain, const Universe& universe,
                                       const State& state, const Goal& goal);

// The facts of `state` that mention only objects in `objects` (sorted).
State project_state(const State& state, const std::vector<ObjectId>& objects);

}  // namespace apprentice
