// The knowledge store: one SQLite file holding the goals and rules the
// agent learned, with where each came from.
//
// Each piece is written in its own transaction the moment it is learned or
// confirmed, so killing the process loses nothing already confirmed. A
// store written by an incompatible version is refused, never misread; a
// damaged one (SQLite's quick_check, or an entry that does not read) is
// refused, never half-used.
//
// Processes share a store through two kinds of lock. SQLite's own locks
// (with a busy timeout of 5 s) let several processes read and write it at
// once, each transaction whole. And each open store holds an flock(2) on
// its file: shared, except for StoreAccess::kFresh, which starts the store
// over and so holds it exclusively; an open that cannot get its lock is
// refused as "in use", so a store another process has open is never
// emptied, deleted or truncated.
//
// A new store is made whole under a temporary name and moved into place
// (knowledge/store_creation.h): killed at any point, a process leaves the
// path either absent or a complete store, never an empty file.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "knowledge/goal_memory.h"
#include "knowledge/matcher.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/file.h"
#include "util/result.h"
#include "world/domain.h"

namespace SQLite {
class Database;
}

namespace apprentice {

inline constexpr int kKnowledgeSchemaVersion = 1;

// How a command uses a store.
enum class StoreAccess {
  // Read and write (teach): a missing or empty file becomes a new store.
  kReadWrite,
  // Read only (knowledge, run): the file must already be a store; nothing
  // is written to it, except that SQLite completes the rollback of a
  // transaction a killed writer left unfinished.
  kReadOnly,
  // Start over (experiment --knowledge-out): a missing file becomes a new
  // store, an existing store is emptied; refused ("in use") while another
  // process has the store open, and held exclusively until closed.
  kFresh,
};

// Everything the agent knows, in memory.
struct Knowledge {
  std::vector<TaskKnowledge> tasks;
  GoalMemory goals;
  RuleMatcher rules;

  const TaskKnowledge* find_task(const std::string& name) const;
};

// Owns its SQLite connection; move-only. Use one KnowledgeStore per
// thread.
class KnowledgeStore {
 public:
  // Opens the store at `path` for `access`. Errors name the file:
  //   kNotFound            kReadOnly and there is no such file
  //   kInvalidInput        it is a directory
  //   kFailedPrecondition  not an apprentice knowledge store (an empty file
  //                        for kReadOnly, another program's file or SQLite
  //                        database), or one of another schema version
  //   kDataLoss            damaged: SQLite's quick_check fails, or a table
  //                        is missing
  //   kIo                  in use by another process (see above); it cannot
  //                        be created, opened or written
  static Result<KnowledgeStore> open(const std::filesystem::path& path,
                                     StoreAccess access = StoreAccess::kReadWrite);

  KnowledgeStore(KnowledgeStore&&) noexcept;
  KnowledgeStore& operator=(KnowledgeStore&&) noexcept;
  ~KnowledgeStore();

  // Durable once this returns successfully.
  Status save_goal(const GoalKnowledge& goal);
  Status save_rule(const Domain& domain, const Rule& rule);
  // Replaces the structure stored under the same task name.
  Status save_task(const TaskKnowledge& task);

  // Forgetting, for the teacher's "undo" and "forget": each is durable once
  // it returns, and removing what is not stored is not an error.
  Status remove_goal(const GoalKey& key);
  Status remove_rule(const Domain& domain, const Rule& rule);
  Status remove_task(const std::string& name);

  // Reads everything back. Goals and rules name predicates and actions,
  // which must exist in `domain` with the arity stored (kFailedPrecondition
  // otherwise); an entry that is not what this version writes (a task
  // structure that is not a list of subtasks, a goal with no literals, a
  // number where a name belongs) is kDataLoss.
  Result<Knowledge> load(const Domain& domain) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  KnowledgeStore(std::filesystem::path path, FileDescriptor lock, std::unique_ptr<SQLite::Database> db);

  std::filesystem::path path_;
  // The descriptor holding the flock(2). Declared before db_, so closed
  // after the database: closing any descriptor of a file drops the
  // process's POSIX locks on it, SQLite's among them.
  FileDescriptor lock_;
  std::unique_ptr<SQLite::Database> db_;
};

// The knowledge in the store at `path`, read once and read-only (what
// `experiment --knowledge-in` and the Python module's knowledge_in start
// from); the store is left as it was. Errors: those of open and load.
Result<Knowledge> load_knowledge_read_only(const std::filesystem::path& path, const Domain& domain);

}  // namespace apprentice
