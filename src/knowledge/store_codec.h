// How each kind of learned knowledge is written as text in a store, the
// same for every engine (knowledge/sqlite_store.h, knowledge/postgres_store.h):
// a goal's literals, a rule's body and a task's structure are JSON.
//
// The readers are strict: a value of another type is never converted
// (nlohmann would turn 1e300 into an int, and 0.5 into an index). An entry
// that is not what this version writes is kDataLoss ("a stored entry is
// unreadable: <entry>: <why>"); one that names a predicate or action the
// domain lacks is kFailedPrecondition. Nothing is thrown out of these
// functions. Engines put their location in front of the message.
#pragma once

#include <string>
#include <string_view>

#include "knowledge/goal_memory.h"
#include "knowledge/preferences.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/result.h"
#include "world/domain.h"

namespace apprentice::store_codec {

std::string encode_goal_literals(const GoalKnowledge& goal);
std::string encode_rule(const Domain& domain, const Rule& rule);
std::string encode_subtasks(const TaskKnowledge& task);
// A class rule whole: its class, modifiers, rest, destination (as goal
// literals), exceptions, source, sentence, evidence, confidence and scope.
std::string encode_class_rule(const ClassRule& rule);

// The stored goal under `key` whose literals are `literals`.
Result<GoalKnowledge> decode_goal(const Domain& domain, GoalKey key, std::string_view literals, Provenance provenance);
// A stored rule from its body.
Result<Rule> decode_rule(const Domain& domain, std::string_view body, Provenance provenance);
// The stored task `name` from its structure.
Result<TaskKnowledge> decode_task(const std::string& name, std::string_view structure);
// A stored class rule from its body; its destination's predicates must be
// the domain's (kFailedPrecondition otherwise, as for goals).
Result<ClassRule> decode_class_rule(const Domain& domain, std::string_view body);

// How entries are named in messages: "the goal for ketchup (clear)",
// "a rule", "the task \"tidy kitchen\"".
std::string goal_entry(const GoalKey& key);
std::string task_entry(const std::string& name);
inline constexpr const char* kRuleEntry = "a rule";
inline constexpr const char* kClassRuleEntry = "a class rule";

// The error for an entry that does not read: kDataLoss "a stored entry is
// unreadable: <entry>: <why>".
Error unreadable(const std::string& entry, const std::string& why);

}  // namespace apprentice::store_codec
