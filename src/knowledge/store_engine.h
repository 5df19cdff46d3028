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
#include "knowledge/store_access.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/result.h"
#include "world/domain.h"

namespace apprentice {

// The version of the stores' schema this program reads and writes.
inline constexpr int kKnowledgeSchemaVersion = 1;

// Everything the agent knows, in memory.
struct Knowledge {
  std::vector<TaskKnowledge> tasks;
  GoalMemory goals;
  RuleMatcher rules;

  const TaskKnowledge* find_task(const std::string& name) const;
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

  // Everything stored, read against `domain` (store_codec.h says which
  // entries are refused, and how).
  virtual Result<Knowledge> load(const Domain& domain) const = 0;
};

}  // namespace apprentice
