// What the agent knows, in plain English, for `apprentice knowledge`: the
// task structures, goals and policy rules it has learned, and where each
// came from. (format_goal_knowledge and format_rule give the PDDL-like
// form, for `knowledge --pddl`.)
#pragma once

#include <string>

#include "knowledge/goal_memory.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "world/domain.h"

namespace apprentice {

// "To tidy the kitchen: clear what is on the table, then store what is on
// the counter, then unload what is in the dish rack."
std::string explain_task(const TaskKnowledge& task);

// "When I clear the table (to tidy the kitchen), a ceramic plate goes in
// the dishwasher, and the dishwasher ends closed."
std::string explain_goal(const GoalKnowledge& goal);

// "When the goal is that the object is in a receptacle and the receptacle
// is closed, and the receptacle is closed, has a door, and my hand is
// empty: open the receptacle (3 steps from the goal)."
std::string explain_rule(const Domain& domain, const Rule& rule);

// "learned on ceramic-plate1 from the instructor: "If the object ..."".
std::string explain_provenance(const Provenance& provenance);

// Where a goal or rule came from, in words: "the instructor, who said
// "..."", "weighing what I knew: clothes go in the hamper, as said: "..."".
std::string explain_source(const std::string& source);

}  // namespace apprentice
