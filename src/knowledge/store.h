// The knowledge store: the goals, rules and task structures the agent
// learned, with where each came from, kept by one of two engines chosen by
// the form of the location:
//   - a path: an SQLite file, the embedded default (knowledge/sqlite_store.h);
//   - a URL, postgresql://USER@HOST:PORT/DB or postgres://...: a PostgreSQL
//     database a fleet of robots shares (knowledge/postgres_store.h).
// Every engine keeps the promises of knowledge/store_engine.h: each piece
// is written in its own transaction the moment it is learned or confirmed,
// so killing the process loses nothing already confirmed; a store written
// by an incompatible version is refused, never misread; a damaged one is
// refused, never half-used; a store in use is never emptied.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "knowledge/store_engine.h"
#include "knowledge/store_location.h"
#include "util/result.h"
#include "world/domain.h"

namespace apprentice {


// Owns its engine and its connection; move-only. Use one KnowledgeStore per
// thread.
class KnowledgeStore {
 public:
  // Opens the store at `location` for `access`. Errors name the store:
  //   kNotFound            kReadOnly and there is no such store
  //   kInvalidInput        it is a directory
  //   kFailedPrecondition  not an apprentice knowledge store (an empty file
  //                        for kReadOnly, another program's file or
  //                        database), or one of another schema version
  //   kDataLoss            damaged: SQLite's quick_check fails, or a table
  //                        is missing
  //   kIo                  in use by another process (store_engine.h); it
  //                        cannot be created, opened or written; the
  //                        PostgreSQL server cannot be reached
  // Messages name a PostgreSQL store by its URL without the password.
  //   kInvalidInput        also: `household` cannot name a household
  //                        (check_household_name)
  //                      or `robot` cannot name a robot (check_robot_name)
  // The store is opened for `household`: its goals and tasks are saved,
  // removed and loaded under that name; rules are shared (store_engine.h).
  // Each goal and rule saved is saved with `robot`, which the other robots'
  // news names (StoreNews); empty means default_robot_name().
  static Result<KnowledgeStore> open(const std::string& location, StoreAccess access = StoreAccess::kReadWrite,
                                     const std::string& household = kDefaultHousehold, const std::string& robot = "");

  KnowledgeStore(KnowledgeStore&&) noexcept;
  KnowledgeStore& operator=(KnowledgeStore&&) noexcept;
  ~KnowledgeStore();

  // Durable once this returns successfully.
  Status save_goal(const GoalKnowledge& goal) { return engine_->save_goal(goal); }
  Status save_rule(const Domain& domain, const Rule& rule) { return engine_->save_rule(domain, rule); }
  // Replaces the structure stored under the same task name.
  Status save_task(const TaskKnowledge& task) { return engine_->save_task(task); }

  // Forgetting, for the teacher's "undo" and "forget": each is durable once
  // it returns, and removing what is not stored is not an error.
  Status remove_goal(const GoalKey& key) { return engine_->remove_goal(key); }
  Status remove_rule(const Domain& domain, const Rule& rule) { return engine_->remove_rule(domain, rule); }
  Status remove_task(const std::string& name) { return engine_->remove_task(name); }

  // Class rules (store_engine.h): saved with their evidence; removed; or
  // forgotten, which is remembered so that the rule is not used again.
  Status save_class_rule(const ClassRule& rule) { return engine_->save_class_rule(rule); }
  Status remove_class_rule(const ClassRule& rule) { return engine_->remove_class_rule(rule); }
  Status forget_class_rule(const ClassRule& rule) { return engine_->forget_class_rule(rule); }

  // Reads everything back. Goals and rules name predicates and actions,
  // which must exist in `domain` with the arity stored (kFailedPrecondition
  // otherwise); an entry that is not what this version writes (a task
  // structure that is not a list of subtasks, a goal with no literals, a
  // number where a name belongs) is kDataLoss.
  Result<Knowledge> load(const Domain& domain) const { return engine_->load(domain); }
  // Every household with goals or tasks in the store.
  Result<std::vector<std::string>> households() const { return engine_->households(); }
  // What other processes (other robots) learned since the store was
  // opened, loaded or last asked (StoreEngine::news).
  Result<StoreNews> news(const Domain& domain) { return engine_->news(domain); }
  const std::string& household() const { return household_; }
  // The name saved with each goal and rule this store saves.
  const std::string& robot() const { return robot_; }

  // Where the store is, as messages name it: the SQLite file's path, or
  // the PostgreSQL URL without its password.
  const std::filesystem::path& path() const { return location_; }
  std::string location() const { return location_.string(); }

 private:
  KnowledgeStore(std::filesystem::path location, std::string household, std::string robot,
                 std::unique_ptr<StoreEngine> engine);

  std::filesystem::path location_;
  std::string household_;
  std::string robot_;
  std::unique_ptr<StoreEngine> engine_;
};

// How much copy_knowledge copied.
struct KnowledgeCopy {
  std::size_t tasks = 0, goals = 0, rules = 0, households = 0, class_rules = 0, forgotten_rules = 0;
};

// Copies everything in the store at `from` (opened read-only, left as it
// was) into the store at `to` (created if missing), every household into
// the household of the same name, in the order it was learned, each entry
// its own durable save: what `to` held stays, except that a goal under the
// same key, or a task of the same name, in the same household, is replaced
// (a rule already there is kept). The engines may differ: this is how
// knowledge moves between SQLite and PostgreSQL. Stopped part way, it
// leaves `to` with a prefix of the copy, and running it again completes
// it. Errors: those of open, load and each save.
Result<KnowledgeCopy> copy_knowledge(const std::string& from, const std::string& to, const Domain& domain);

// The knowledge of `household` in the store at `location`, read once and read-only (what
// `experiment --knowledge-in` and the Python module's knowledge_in start
// from); the store is left as it was. Errors: those of open and load.
Result<Knowledge> load_knowledge_read_only(const std::string& location, const Domain& domain,
                                            const std::string& household = kDefaultHousehold);

}  // namespace apprentice
