// The SQL both knowledge store engines run (knowledge/sqlite_store.cc,
// knowledge/postgres_store.cc), written once, with SQLite's `?`
// placeholders: the PostgreSQL engine numbers them ($1, $2, ...) with
// numbered_placeholders. Only what the engines' SQL dialects cannot share
// stays in the engine: an upsert that gives a replaced entry a new id (and
// PostgreSQL's NOTIFY), the id column's type, and the migration from
// version 1, which SQLite cannot do with ALTER TABLE. SqlEngine below does
// what both do the same way on this SQL.
//
// Every statement here reads the same in both dialects: standard SQL, text
// parameters, CAST(? AS TEXT) where PostgreSQL must know a parameter's type.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "knowledge/store_engine.h"

namespace apprentice::store_sql {

// `sql` with its n-th `?` written `$n`, for PostgreSQL. The SQL here has
// no `?` inside a quoted literal.
std::string numbered_placeholders(std::string_view sql);

// The current schema's tables, created in an empty database, with `id` for
// the type of each auto-numbered id column ("INTEGER PRIMARY KEY
// AUTOINCREMENT" on SQLite, "BIGSERIAL PRIMARY KEY" on PostgreSQL): ids
// are never used again, so that what another process saved is what comes
// after the last id seen (StoreEngine::news). One statement per entry.
std::vector<std::string> schema(std::string_view id);
// Of them, class_rules and forgotten_rules, which version 3 added
// (version 2 to 3 creates them).
std::vector<std::string> class_rules_tables(std::string_view id);
// The id column's type on each engine.
inline constexpr std::string_view kSqliteId = "INTEGER PRIMARY KEY AUTOINCREMENT";
inline constexpr std::string_view kPostgresId = "BIGSERIAL PRIMARY KEY";
inline constexpr const char* kInsertMeta = "INSERT INTO meta(key, value) VALUES ('format', ?), ('schema_version', ?)";
inline constexpr const char* kSetVersion = "UPDATE meta SET value = ? WHERE key = 'schema_version'";
inline constexpr const char* kReadMeta = "SELECT key, value FROM meta";

// Version 3 to 4: each goal and rule names the robot that saved it (the
// name it opened the store with, KnowledgeStore::open); what there was is
// no robot's, '' ("another robot" in the news).
inline constexpr const char* kMigration3To4[] = {"ALTER TABLE goals ADD COLUMN robot TEXT NOT NULL DEFAULT ''",
                                                 "ALTER TABLE rules ADD COLUMN robot TEXT NOT NULL DEFAULT ''"};

// What version meta names: kOldestMigratedSchemaVersion ..
// kKnowledgeSchemaVersion, or 0 for anything else.
int version_number(const std::string& text);

// The message for a store (named `where`) of another schema version.
std::string other_version(const std::string& where, const std::string& version);

// What load() reads (each with the household as its one parameter, except
// kRules): the columns a store must have, or it is damaged. A store of
// version 1, read as it is (opened read-only), holds the default
// household's goals and tasks alone.
inline constexpr const char* kTasks = "SELECT name, structure FROM tasks WHERE household = ? ORDER BY name";
inline constexpr const char* kGoals =
    "SELECT task, subtask, category, place, literals, object, source FROM goals WHERE household = ? ORDER BY id";
inline constexpr const char* kTasksV1 = "SELECT name, structure FROM tasks WHERE CAST(? AS TEXT) = 'default' ORDER BY name";
inline constexpr const char* kGoalsV1 =
    "SELECT task, subtask, category, place, literals, object, source FROM goals WHERE CAST(? AS TEXT) = 'default' "
    "ORDER BY id";
inline constexpr const char* kRules = "SELECT body, object, source FROM rules ORDER BY id";
// The other households' goals: the fleet's prior (version 2 on).
inline constexpr const char* kFleetGoals =
    "SELECT household, task, subtask, category, place, literals, object, source FROM goals WHERE household <> ? "
    "ORDER BY id";
inline constexpr const char* kClassRules = "SELECT body FROM class_rules WHERE household = ? ORDER BY id";
inline constexpr const char* kForgottenRules = "SELECT body FROM forgotten_rules WHERE household = ? ORDER BY id";
// The households, by the store's version.
inline constexpr const char* kHouseholds =
    "SELECT household FROM goals UNION SELECT household FROM tasks UNION SELECT household FROM class_rules "
    "UNION SELECT household FROM forgotten_rules ORDER BY 1";
inline constexpr const char* kHouseholdsV2 = "SELECT household FROM goals UNION SELECT household FROM tasks ORDER BY 1";
inline constexpr const char* kHouseholdsV1 =
    "SELECT 'default' WHERE EXISTS(SELECT 1 FROM goals) OR EXISTS(SELECT 1 FROM tasks)";
const char* households_query(int version);

// The robot column of goals and rules as a store of `version` has it:
// "robot", or '' before version 4 (read as it is).
std::string robot_column(int version);
// One goal of the household by its key (household, task, subtask,
// category, place): literals, object, source, robot.
std::string goal_by_key(int version);
// One rule by its signature: body, object, source, robot.
std::string rule_by_signature(int version);
// What was saved after the last ids seen (household, last goal id; last
// rule id), as goal_by_key and rule_by_signature read it after the id.
std::string new_goals(int version);
std::string new_rules(int version);
inline constexpr const char* kLastIds =
    "SELECT (SELECT coalesce(max(id), 0) FROM goals), (SELECT coalesce(max(id), 0) FROM rules)";

// Removing, by key.
inline constexpr const char* kRemoveGoal =
    "DELETE FROM goals WHERE household = ? AND task = ? AND subtask = ? AND category = ? AND place = ?";
inline constexpr const char* kRemoveRule = "DELETE FROM rules WHERE signature = ?";
inline constexpr const char* kRemoveTask = "DELETE FROM tasks WHERE household = ? AND name = ?";
inline constexpr const char* kRemoveClassRule = "DELETE FROM class_rules WHERE household = ? AND key = ?";
inline constexpr const char* kUnforgetClassRule = "DELETE FROM forgotten_rules WHERE household = ? AND key = ?";
// Starting a store over (StoreAccess::kFresh), one statement each.
inline constexpr const char* kStartOver[] = {"DELETE FROM goals", "DELETE FROM tasks", "DELETE FROM rules",
                                             "DELETE FROM class_rules", "DELETE FROM forgotten_rules"};

// The SQL above names the default household as a literal.
static_assert(std::string_view(kDefaultHousehold) == "default");

// What both engines do the same way, on the SQL above: an engine opened for
// one household and one robot, whose removals are one statement each.
class SqlEngine : public StoreEngine {
 public:
  SqlEngine(std::string household, std::string robot) : household_(std::move(household)), robot_(std::move(robot)) {}

  Status remove_goal(const GoalKey& key) final;
  Status remove_rule(const Domain& domain, const Rule& rule) final;
  Status remove_task(const std::string& name) final;
  Status remove_class_rule(const ClassRule& rule) final;

 protected:
  // Runs `sql`, one statement of this header (`?` placeholders), in its own
  // transaction with the text parameters `values`; durable once it returns.
  virtual Status execute(const char* sql, const std::vector<std::string>& values) = 0;

  const std::string household_;
  // The robot saved with each goal and rule.
  const std::string robot_;
};

}  // namespace apprentice::store_sql
