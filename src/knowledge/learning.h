// Policy learning by dependency analysis of what was executed.
//
// When a goal has been achieved, the agent goes back over the actions it
// executed for it (retrospective analysis). Regressing the goal through the
// actions from last to first finds, for each action, the facts of the state
// before it on which the rest of the plan depended. Each action that
// contributed to the goal becomes a rule whose conditions are only those
// facts and the goal, with object identities turned into variables. Actions
// that contributed nothing (detours) give no rule, nor do actions that only
// lead back to a state the episode had already been in (loops).
#pragma once

#include <string>
#include <vector>

#include "knowledge/rule.h"
#include "util/result.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/state.h"

namespace apprentice {

enum class Generalization {
  // Like the paper's chunks: each rule tests the subtask and the category
  // of every object its action manipulates other than the object of
  // interest (an open rule for the dishwasher opens only dishwashers).
  kPaper,
  // Only what the dependency analysis needs: no category is ever a
  // precondition of an action, so no rule tests one, and no rule tests the
  // subtask. An open rule then serves any closed receptacle a goal needs,
  // in any subtask.
  kFull,
};

const char* to_string(Generalization generalization);
// "full" or "paper"; kInvalidInput otherwise.
Result<Generalization> parse_generalization(std::string_view text);

struct Episode {
  State initial;                     // the state before the first action
  std::vector<Action> actions;       // executed in order; together they achieve `goal`
  std::vector<std::string> sources;  // where each action came from, one per action
  Goal goal;
  ObjectId object_of_interest = 0;
  std::string subtask;
  std::string object_description;  // for provenance: "ceramic-plate1 (ceramic-plate)"
};

// Returns one rule per contributing action, last action first. The episode
// must be valid: each action applicable in turn and the goal reached at the
// end (checked).
std::vector<Rule> learn_policy_rules(const Domain& domain, const Universe& universe,
                                     const Episode& episode, Generalization generalization);

}  // namespace apprentice
