// The interface every knowledge store engine implements (SQLite,
// knowledge/sqlite_store.h; PostgreSQL, knowledge/postgres_store.h), and
// what they all promise. KnowledgeStore (knowledge/store.h) chooses the
// engine by the form of the location and forwards to it.
//
// Every engine keeps the same promises:
//   - each save and remove is its own transaction, durable once it returns;
//   - a store of another schema version, of another program, or damaged is
//     refused when opened, never misread or half-used;
//   - a store another process has open is never emptied (StoreAccess::kFresh
//     is refused "in use" then);
//   - load() reads one consistent snapshot while writers go on.
//
// Adding a kind of stored knowledge: its text form in store_codec.h, its
// save/remove here, its table in each engine's schema (with a migration
// step from the schema before), and its part of Knowledge, read by load().
#pragma once

#include <string>
#include <vector>

#include "knowledge/goal_memory.h"
#include "knowledge/matcher.h"
#include "knowledge/preferences.h"
#include "knowledge/store_access.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/result.h"
#include "world/domain.h"

namespace apprentice {

// The version of the stores' schema this program reads and writes. A store
// of an earlier version is brought up to this one when opened for writing
// (each engine's migration steps), and read as it is when opened read-only.
//   1  tasks, goals, rules
//   2  class_rules and forgotten_rules (a person's and induced class rules,
//      with their evidence; the rules forgotten)
inline constexpr int kKnowledgeSchemaVersion = 2;
// The earliest version still read.
inline constexpr int kOldestKnowledgeSchemaVersion = 1;

// Everything the agent knows, in memory.
struct Knowledge {
  std::vector<TaskKnowledge> tasks;
  GoalMemory goals;
  RuleMatcher rules;
  // Class rules (knowledge/preferences.h) with their evidence: a person's,
  // kept when said, and those induced from the goals, kept when a session
  // ends. In the order learned.
  ClassRules class_rules;
  // The rules the person told the agent to forget: never used again, even
  // where the goals would induce them anew, until said again.
  ClassRules forgotten_rules;

  const TaskKnowledge* find_task(const std::string& name) const;
  // Whether `rule` (by class_rule_key) was forgotten.
  bool forgot(const ClassRule& rule) const { return forgotten_rules.find(rule) != nullptr; }
};

class StoreEngine {
 public:
  virtual ~StoreEngine() = default;

  // Durable once each returns successfully. save_goal replaces the goal
  // under the same key, save_task the structure under the same task name;
  // save_rule ignores a rule already stored (the same signature).
  virtual Status save_goal(const GoalKnowledge& goal) = 0;
  virtual Status save_rule(const Domain& domain, const Rule& rule) = 0;
  virtual Status save_task(const TaskKnowledge& task) = 0;

  // Removing what is not stored is not an error.
  virtual Status remove_goal(const GoalKey& key) = 0;
  virtual Status remove_rule(const Domain& domain, const Rule& rule) = 0;
  virtual Status remove_task(const std::string& name) = 0;

  // Class rules, by class_rule_key. save_class_rule replaces the rule
  // under the same key and takes it off the forgotten list (a rule said
  // again is meant); remove_class_rule removes it (undo); forget_class_rule
  // removes it and puts it on the forgotten list, so that it is not used
  // again after a reload.
  virtual Status save_class_rule(const ClassRule& rule) = 0;
  virtual Status remove_class_rule(const ClassRule& rule) = 0;
  virtual Status forget_class_rule(const ClassRule& rule) = 0;

  // Everything stored, read against `domain` (store_codec.h says which
  // entries are refused, and how).
  virtual Result<Knowledge> load(const Domain& domain) const = 0;
};

}  // namespace apprentice
