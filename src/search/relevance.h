// Which objects can matter to a goal. Search grounds and expands actions
// over these objects only, so that a world with thousands of irrelevant
// objects costs no more to plan in than one without them.
//
// The decision is made from the domain, so that it stays sound in domains
// where objects interact (dishes that stack, a lid that closes a pot, a
// drawer inside a cupboard). An object may be left out only if removing
// every action that mentions it from any plan leaves a plan that still
// reaches the goal. That holds for object o when:
//
//   1. the goal does not mention o, and o is not in the hand;
//   2. every action o can take part in is *local* to o's parameter: each
//      of its effects either mentions that parameter or is the hand's own
//      bookkeeping (see 3). An action that changes a fact about another
//      object ((covered ?bottom) when ?top is unstacked, (closed ?pot) when
//      the ?lid is lifted) makes every object that can fill that
//      parameter relevant. "Can fill" uses the parameter's type and its
//      one-argument static preconditions, such as (grabbable ?o);
//   3. the hand is a one-arm hand: a zero-argument fact h and a
//      one-argument fact g such that every action that deletes h requires
//      h and adds exactly one g fact; every action that adds h requires
//      and deletes one g fact; nothing else adds or deletes them; no
//      action and no goal requires h or g to be false; and the initial
//      state has exactly one of h and the g facts. Then at most one object
//      is held at a time, and an object picked up and put back changes
//      nothing for the others: the kitchen's (handempty) and (holding ?o).
//
// Under 1-3, an action that does not mention o never reads a fact about o,
// and the actions that mention o change only facts about o and the hand,
// so dropping them keeps every other action applicable (the proof is in
// docs/domain.md). Kitchen items satisfy 2 and 3, so they are pruned;
// places are not (putting an item on a surface changes a fact about the
// item, not only about the surface), so they are always kept.
#pragma once

#include <string>
#include <vector>

#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

// What the domain alone says about interaction: computed once per domain.
struct DomainInteraction {
  struct Hand {
    PredicateId empty = 0;    // h, such as (handempty)
    PredicateId holding = 0;  // g, such as (holding ?o)
  };
  // The one-arm hands found (usually none or one).
  std::vector<Hand> hands;
  // For each action schema and each of its parameters: false when the
  // action changes a fact that does not mention that parameter (other than
  // a hand's), so any object that can fill it must be kept.
  std::vector<std::vector<bool>> local;
  // For each non-local parameter, why: "unstack changes (covered ?bottom)".
  std::vector<std::vector<std::string>> reason;
};

DomainInteraction analyze_interaction(const Domain& domain);

struct Relevance {
  std::vector<ObjectId> objects;  // the relevant objects, sorted
  // Objects kept only because they can interact with others (condition 2),
  // not counting places and goal objects that would be kept anyway.
  std::size_t kept_for_interaction = 0;
  std::size_t pruned = 0;  // objects left out
  // Sentences for --verbose: what was pruned and why it is safe, or why
  // pruning is off.
  std::vector<std::string> notes;
};

// Applies conditions 1-3 to every object. Visits only the goal's objects,
// the held ones and the objects of the types that can fill a non-local
// parameter (the places, in the kitchen), with O(log n) queries on the
// state: sublinear in the number of items.
Relevance analyze_relevance(const Domain& domain, const Universe& universe, const State& state, const Goal& goal);

// The relevant objects of analyze_relevance (sorted ids).
std::vector<ObjectId> relevant_objects(const Domain& domain, const Universe& universe,
                                       const State& state, const Goal& goal);

// The facts of `state` that mention only objects in `objects` (sorted).
State project_state(const State& state, const std::vector<ObjectId>& objects);

// What a planner grounds over: with `prune`, the relevant objects and the
// state projected onto them; without, every object and the state as it is.
struct SearchScope {
  std::vector<ObjectId> objects;  // sorted
  State state;
  std::vector<std::string> notes;  // Relevance::notes, or that pruning is off
};
SearchScope search_scope(const Domain& domain, const Universe& universe, const State& state, const Goal& goal,
                         bool prune);

}  // namespace apprentice
