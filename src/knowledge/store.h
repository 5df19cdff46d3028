// The knowledge store: one SQLite file holding the goals and rules the
// agent learned, with where each came from.
//
// Each piece is written in its own transaction the moment it is learned or
// confirmed, so killing the process loses nothing already confirmed. A
// store written by an incompatible version is refused, never misread.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "knowledge/goal_memory.h"
#include "knowledge/matcher.h"
#include "knowledge/rule.h"
#include "knowledge/task_knowledge.h"
#include "util/result.h"
#include "world/domain.h"

namespace SQLite {
class Database;
}

namespace apprentice {

inline constexpr int kKnowledgeSchemaVersion = 1;

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
  // Opens the store, creating an empty one if the file does not exist.
  // kFailedPrecondition for a store of another schema version or another
  // program's database; kDataLoss if the file is not a readable database;
  // kIo if it cannot be created.
  static Result<KnowledgeStore> open(const std::filesystem::path& path);

  KnowledgeStore(KnowledgeStore&&) noexcept;
  KnowledgeStore& operator=(KnowledgeStore&&) noexcept;
  ~KnowledgeStore();

  // Durable once this returns successfully.
  Status save_goal(const GoalKnowledge& goal);
  Status save_rule(const Domain& domain, const Rule& rule);
  // Replaces the structure stored under the same task name.
  Status save_task(const TaskKnowledge& task);

  // Reads everything back; rules name predicates and actions, which must
  // exist in `domain` (kFailedPrecondition otherwise).
  Result<Knowledge> load(const Domain& domain) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  KnowledgeStore(std::filesystem::path path, std::unique_ptr<SQLite::Database> db);

  std::filesystem::path path_;
  std::unique_ptr<SQLite::Database> db_;
};

}  // namespace apprentice
