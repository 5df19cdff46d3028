// What the other households of a store taught: the fleet as a knowledge
// source (ProposalSource::kFleet). For a kind this household never taught,
// the destinations other households chose for it, each with how many of
// them chose it; the agent weighs them with its other sources
// (knowledge/decision.h) and, in doubt, asks "In most households I know
// of (3 of 4), the ketchup goes in the fridge. Here too?".
//
// Goal preferences are a household's own (knowledge/store_engine.h): the
// prior never replaces what this household taught, and what it proposes is
// a question, not a fact, until the decision is sure enough.
#pragma once

#include <string>
#include <vector>

#include "knowledge/decision.h"
#include "knowledge/goal_memory.h"

namespace apprentice {

// A goal another household taught.
struct FleetGoal {
  std::string household;
  GoalKnowledge goal;
};

class FleetPrior {
 public:
  void add(std::string household, GoalKnowledge goal);
  const std::vector<FleetGoal>& all() const { return goals_; }
  bool empty() const { return goals_.empty(); }
  std::size_t size() const { return goals_.size(); }

  // Where the other households put things of `key.category`: those that
  // taught the kind in the same task, subtask and kind of place, or, when
  // none did, in the same task (its first placement there). Goals that are
  // not a placement alone (knowledge/preferences.h, destination_of) are
  // not counted. Each household counts once. One proposal per destination
  // chosen, with `households` and `of_households` set; its confidence is
  // Laplace's rule of succession over the destinations named and
  // "elsewhere": (chose it + 1) / (households + destinations + 1). One
  // household's choice is 2/3 sure; 9 of 9 agreeing, 10/11; 3 of 4, with
  // one other place named, 4/7. Empty when no other household taught it.
  std::vector<DestinationProposal> propose(const GoalKey& key) const;

 private:
  std::vector<FleetGoal> goals_;
};

}  // namespace apprentice
