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
//   - load() reads one consistent snapshot while writers go on;
//   - an engine is opened for one household (kDefaultHousehold unless
//     named): its goals and task structures are that household's alone,
//     saved, removed and loaded under its name, so two households that
//     want different places for one kind never overwrite each other; its
//     rules are the fleet's, shared by every household of the store;
//   - a store of an older schema version is migrated when opened to write
//     (one step per version, in one transaction), and read as it is when
//     opened read-only.
//
//   - an engine is opened for one robot, a name saved with each goal and
//     rule it saves (the news names it).
//
// Adding a kind of stored knowledge: its text form in store_codec.h, its
// save/remove here, its table in the schema (knowledge/store_sql.h, with a
// migration step from the schema before), and its part of Knowledge, read
// by load().
#pragma once

#include <string>
#include <vector>

#include "knowledge/fleet_prior.h"
#include "knowledge/goal_memory.h"
#include "knowledge/matcher.h"
#include "knowledge/preferences.h"
#include "knowledge/store_access.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/result.h"
#include "world/domain.h"

namespace apprentice {

// The version of the stores' schema this program reads and writes.
//   1  tasks, goals, rules (one household)
//   2  goals and tasks belong to a household (a `household` column, part of
//      their keys); what version 1 held is the default household's
//   3  class_rules and forgotten_rules, a household's: its rules about
//      classes of things with their evidence, and those it forgot
//   4  goals and rules name the robot that saved them (a `robot` column;
//      '' for what was saved before, by a robot the store does not know)
// Each engine migrates a store one step at a time from the oldest version
// it still reads, kOldestMigratedSchemaVersion.
inline constexpr int kKnowledgeSchemaVersion = 4;
inline constexpr int kOldestMigratedSchemaVersion = 1;

// Everything the agent knows, in memory.
struct Knowledge {
  std::vector<TaskKnowledge> tasks;
  GoalMemory goals;
  RuleMatcher rules;
  // Class rules (knowledge/preferences.h) with their evidence: a person's,
  // kept when said, and those induced from the goals, kept when a session
  // ends; the household's, in the order learned.
  ClassRules class_rules;
  // The rules the person told the agent to forget: never used again, even
  // where the goals would induce them anew, until said again.
  ClassRules forgotten_rules;
  // The goals every other household of the store taught (the fleet's
  // prior, knowledge/fleet_prior.h), in the order saved. Those that name
  // what `domain` lacks (another world's) are left out.
  FleetPrior fleet;

  const TaskKnowledge* find_task(const std::string& name) const;
  // Whether `rule` (by class_rule_key) was forgotten.
  bool forgot(const ClassRule& rule) const { return forgotten_rules.find(rule) != nullptr; }
};

// What other processes saved into a store since it was opened, loaded or
// last asked (StoreEngine::news): the goals of its household and the
// fleet's rules, whole, in the order they were saved, each with the robot
// that saved it.
struct StoreNews {
  std::vector<GoalKnowledge> goals;
  std::vector<Rule> rules;
  // The robot that saved each of `goals`, in the same order: the name it
  // opened the store with (KnowledgeStore::open), or "" for a goal saved
  // before the store's schema named robots (version 4).
  std::vector<std::string> goal_robots;
  bool empty() const { return goals.empty() && rules.empty(); }
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

  // Class rules, the household's, by class_rule_key. save_class_rule
  // replaces the rule under the same key and takes it off the forgotten
  // list (a rule said again is meant); remove_class_rule removes it (undo);
  // forget_class_rule removes it and puts it on the forgotten list, so that
  // it is not used again after a reload.
  virtual Status save_class_rule(const ClassRule& rule) = 0;
  virtual Status remove_class_rule(const ClassRule& rule) = 0;
  virtual Status forget_class_rule(const ClassRule& rule) = 0;

  // Everything stored, read against `domain` (store_codec.h says which
  // entries are refused, and how).
  virtual Result<Knowledge> load(const Domain& domain) const = 0;

  // The households that have goals or tasks in the store, by name.
  virtual Result<std::vector<std::string>> households() const = 0;

  // What another process saved since this engine was opened, loaded or
  // last asked: goals of this household, rules of any (StoreNews). Cheap
  // when nothing changed, and never waits: SQLite compares PRAGMA
  // data_version, which changes when another connection commits;
  // PostgreSQL reads the notifications its LISTEN received (every save
  // sends one, NOTIFY, in the save's own transaction). The news may hold
  // what this process saved itself meanwhile (SQLite, when another process
  // saved too): callers keep what they know already. A goal removed again
  // before it was asked about is not news.
  virtual Result<StoreNews> news(const Domain& domain) = 0;
};

}  // namespace apprentice
