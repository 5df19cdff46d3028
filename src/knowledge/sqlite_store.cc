#include "knowledge/sqlite_store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string_view>

#include <SQLiteCpp/SQLiteCpp.h>

#include "knowledge/store_engine.h"
#include "knowledge/store_codec.h"
#include "knowledge/store_creation.h"
#include "knowledge/store_sql.h"
#include "util/file.h"

namespace apprentice {

namespace {

constexpr int kBusyTimeoutMs = 5000;

using Texts = std::vector<std::string>;
using Statements = std::vector<std::pair<const char*, Texts>>;

// What an SQLite failure means to the user, by SQLite's result code.
Error sqlite_error(const std::filesystem::path& path, const std::exception& e) {
  const std::string where = path.string() + ": ";
  const auto* sqlite = dynamic_cast<const SQLite::Exception*>(&e);
  const int code = sqlite ? sqlite->getErrorCode() : SQLITE_ERROR;
  switch (code) {
    case SQLITE_NOTADB:
      return Error{ErrorCode::kFailedPrecondition, where + "not an apprentice knowledge store (not an SQLite database)"};
    case SQLITE_CORRUPT:
      return Error{ErrorCode::kDataLoss, where + "the knowledge store is damaged (" + e.what() + ")"};
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return Error{ErrorCode::kIo, where + "the knowledge store is in use by another process and stayed locked for " +
                                       std::to_string(kBusyTimeoutMs / 1000) + " s (" + e.what() + ")"};
    case SQLITE_FULL: return Error{ErrorCode::kIo, where + "the disk is full (" + e.what() + ")"};
    default: return Error{ErrorCode::kIo, where + e.what()};
  }
}

tl::unexpected<Error> damaged(const std::filesystem::path& path, const std::string& what) {
  return make_error(ErrorCode::kDataLoss, path.string() + ": the knowledge store is damaged: " + what);
}

tl::unexpected<Error> not_a_store(const std::filesystem::path& path, const std::string& why) {
  return make_error(ErrorCode::kFailedPrecondition, path.string() + ": not an apprentice knowledge store (" + why + ")");
}

namespace sql = store_sql;

tl::unexpected<Error> other_version(const std::string& where, const std::string& version) {
  return make_error(ErrorCode::kFailedPrecondition, sql::other_version(where, version));
}

int table_count(SQLite::Database& db) {
  SQLite::Statement tables(db, "SELECT count(*) FROM sqlite_master WHERE type='table'");
  tables.executeStep();
  return tables.getColumn(0).getInt();
}

// The schema version in meta, or the store's error.
Result<std::string> read_version(SQLite::Database& db, const std::filesystem::path& path) {
  std::string format, version;
  SQLite::Statement meta(db, sql::kReadMeta);
  while (meta.executeStep()) {
    std::string key = meta.getColumn(0).getString();
    if (key == "format") format = meta.getColumn(1).getString();
    if (key == "schema_version") version = meta.getColumn(1).getString();
  }
  if (format != kKnowledgeFormatName)
    return make_error(ErrorCode::kFailedPrecondition, path.string() + " is not an apprentice knowledge store");
  return version;
}

// Migrates a store of an older version (`may_write`), in an immediate
// transaction that reads the version again, so that two processes opening
// one old store migrate it once. Returns the version now in the store.
Result<int> migrate_if_old(SQLite::Database& db, const std::filesystem::path& path, int version, bool may_write) {
  if (version == kKnowledgeSchemaVersion || !may_write) return version;
  SQLite::Transaction transaction(db, SQLite::TransactionBehavior::IMMEDIATE);
  auto again = read_version(db, path);
  if (!again) return tl::unexpected(again.error());
  const int now = sql::version_number(*again);
  if (now == 0) return other_version(path.string(), *again);
  if (now < kKnowledgeSchemaVersion) migrate_knowledge_schema(db, now);
  transaction.commit();
  return kKnowledgeSchemaVersion;
}

// Checks that the database is a store this version reads with every table
// load() reads, creating the schema in an empty database when `may_create`
// and migrating an older one to this version when `may_create` (a reader
// reads it as it is). Creation happens in an immediate transaction that
// checks again, so two processes creating one store at once make one
// schema. Returns the store's schema version.
Result<int> check_or_create_schema(SQLite::Database& db, const std::filesystem::path& path, bool may_create) {
  if (!db.tableExists("meta")) {
    if (table_count(db) > 0)
      return make_error(ErrorCode::kFailedPrecondition,
                        path.string() + " is an SQLite database of another program, not an apprentice knowledge store");
    if (!may_create) return not_a_store(path, "an SQLite database with no tables");
    SQLite::Transaction transaction(db, SQLite::TransactionBehavior::IMMEDIATE);
    if (!db.tableExists("meta")) {
      if (table_count(db) > 0)
        return make_error(ErrorCode::kFailedPrecondition,
                          path.string() + " is an SQLite database of another program, not an apprentice knowledge store");
      create_knowledge_schema(db);
    }
    transaction.commit();
  }
  auto found = read_version(db, path);
  if (!found) return tl::unexpected(found.error());
  const int old = sql::version_number(*found);
  if (old == 0) return other_version(path.string(), *found);
  auto version = migrate_if_old(db, path, old, may_create);
  if (!version) return version;
  const bool v1 = *version == 1;
  std::vector<std::pair<const char*, const char*>> tables{
      {"tasks", v1 ? sql::kTasksV1 : sql::kTasks}, {"goals", v1 ? sql::kGoalsV1 : sql::kGoals}, {"rules", sql::kRules}};
  if (*version >= 3) {
    tables.emplace_back("class_rules", sql::kClassRules);
    tables.emplace_back("forgotten_rules", sql::kForgottenRules);
  }
  for (auto [table, query] : tables) {
    try {
      SQLite::Statement check(db, query);
    } catch (const SQLite::Exception& e) {
      if (e.getErrorCode() != SQLITE_ERROR) throw;
      return damaged(path, std::string("its ") + table + " table is missing or incomplete (" + e.what() + ")");
    }
  }
  return *version;
}

// SQLite's quick_check: the pages and indexes are consistent.
Status quick_check(SQLite::Database& db, const std::filesystem::path& path) {
  SQLite::Statement check(db, "PRAGMA quick_check(1)");
  if (!check.executeStep()) return damaged(path, "PRAGMA quick_check gave no answer");
  std::string answer = check.getColumn(0).getString();
  if (answer != "ok") return damaged(path, "PRAGMA quick_check reports " + answer);
  return {};
}

class SqliteStore final : public store_sql::SqlEngine {
 public:
  SqliteStore(std::filesystem::path path, std::string household, std::string robot, int version, FileDescriptor lock,
              std::unique_ptr<SQLite::Database> db)
      : SqlEngine(std::move(household), std::move(robot)), path_(std::move(path)), version_(version),
        lock_(std::move(lock)), db_(std::move(db)) {}
  // The database first, then its lock (see lock_).
  ~SqliteStore() override { db_.reset(); }

  Status save_goal(const GoalKnowledge& goal) override;
  Status save_rule(const Domain& domain, const Rule& rule) override;
  Status save_task(const TaskKnowledge& task) override;
  Result<Knowledge> load(const Domain& domain) const override;
  Result<std::vector<std::string>> households() const override;
  Status save_class_rule(const ClassRule& rule) override;
  Status forget_class_rule(const ClassRule& rule) override;
  Result<StoreNews> news(const Domain& domain) override;
  // Takes what the store holds now as seen (news() reports only what comes
  // after). Throws SQLite::Exception.
  void mark_seen() const;

 private:
  // Runs the statements `statements()` gives in one transaction, each with
  // its text parameters (made inside the try: nothing escapes).
  template <typename Make>
  Status write_all(Make statements);
  // Runs one statement in its own transaction, with the text parameters
  // `parameters()` gives.
  template <typename Parameters>
  Status write(const char* sql, Parameters parameters);
  Status execute(const char* sql, const Texts& values) override {
    return write(sql, [&] { return values; });
  }

  std::filesystem::path path_;
  // The schema version of the store: kKnowledgeSchemaVersion, or an older
  // one a reader reads as it is.
  int version_;
  // What news() has seen: the store's data_version and the last goal and
  // rule ids (a saved or replaced entry gets a new, larger id).
  mutable std::int64_t data_version_ = -1;
  mutable std::int64_t last_goal_id_ = 0;
  mutable std::int64_t last_rule_id_ = 0;
  // The descriptor holding the flock(2). Declared before db_, so closed
  // after the database: closing any descriptor of a file drops the
  // process's POSIX locks on it, SQLite's among them.
  FileDescriptor lock_;
  std::unique_ptr<SQLite::Database> db_;
};

template <typename Make>
Status SqliteStore::write_all(Make statements) {
  try {
    const Statements made = statements();
    SQLite::Transaction transaction(*db_);
    for (const auto& [sql, values] : made) {
      SQLite::Statement statement(*db_, sql);
      for (std::size_t i = 0; i < values.size(); ++i) statement.bind(static_cast<int>(i + 1), values[i]);
      statement.exec();
    }
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
}

template <typename Parameters>
Status SqliteStore::write(const char* sql, Parameters parameters) {
  return write_all([&] { return Statements{{sql, parameters()}}; });
}

Status SqliteStore::save_class_rule(const ClassRule& rule) {
  return write_all([&] {
    const std::string key = class_rule_key(rule);
    return Statements{{sql::kUnforgetClassRule, Texts{household_, key}},
                      {"INSERT OR REPLACE INTO class_rules(household, key, body, source) VALUES (?, ?, ?, ?)",
                       Texts{household_, key, store_codec::encode_class_rule(rule),
                             std::string(rule_source_name(rule.source))}}};
  });
}

Status SqliteStore::forget_class_rule(const ClassRule& rule) {
  return write_all([&] {
    const std::string key = class_rule_key(rule);
    return Statements{{sql::kRemoveClassRule, Texts{household_, key}},
                      {"INSERT OR REPLACE INTO forgotten_rules(household, key, body) VALUES (?, ?, ?)",
                       Texts{household_, key, store_codec::encode_class_rule(rule)}}};
  });
}

// A goal or rule saved again is replaced (INSERT OR REPLACE deletes the
// old row), so it gets a new id and moves to the end.
Status SqliteStore::save_goal(const GoalKnowledge& goal) {
  return write(
      "INSERT OR REPLACE INTO goals(household, task, subtask, category, place, literals, object, source, robot) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
      [&] {
        return Texts{household_,          goal.key.task,          goal.key.subtask,
                     goal.key.category,   goal.key.place,         store_codec::encode_goal_literals(goal),
                     goal.provenance.object, goal.provenance.source, robot_};
      });
}

Status SqliteStore::save_rule(const Domain& domain, const Rule& rule) {
  return write("INSERT OR IGNORE INTO rules(signature, body, object, source, robot) VALUES (?, ?, ?, ?, ?)", [&] {
    return Texts{rule_signature(domain, rule), store_codec::encode_rule(domain, rule), rule.provenance.object,
                 rule.provenance.source, robot_};
  });
}

Status SqliteStore::save_task(const TaskKnowledge& task) {
  return write("INSERT OR REPLACE INTO tasks(household, name, structure) VALUES (?, ?, ?)",
               [&] { return Texts{household_, task.name, store_codec::encode_subtasks(task)}; });
}

void SqliteStore::mark_seen() const {
  data_version_ = db_->execAndGet("PRAGMA data_version").getInt64();
  if (version_ == 1) return;
  SQLite::Statement last(*db_, sql::kLastIds);
  if (!last.executeStep()) return;
  last_goal_id_ = last.getColumn(0).getInt64();
  last_rule_id_ = last.getColumn(1).getInt64();
}

Result<StoreNews> SqliteStore::news(const Domain& domain) {
  StoreNews news;
  auto located = [&](const Error& error) { return tl::unexpected(prefix_error(error, path_.string())); };
  try {
    // A version 1 store (read as it is) has no ids to follow by household.
    if (version_ == 1) return news;
    const std::int64_t now = db_->execAndGet("PRAGMA data_version").getInt64();
    if (now == data_version_) return news;
    SQLite::Transaction snapshot(*db_, SQLite::TransactionBehavior::DEFERRED);
    SQLite::Statement goals(*db_, sql::new_goals(version_));
    goals.bind(1, household_);
    goals.bind(2, last_goal_id_);
    while (goals.executeStep()) {
      last_goal_id_ = std::max(last_goal_id_, goals.getColumn(0).getInt64());
      GoalKey key{goals.getColumn(1).getString(), goals.getColumn(2).getString(), goals.getColumn(3).getString(),
                  goals.getColumn(4).getString()};
      auto goal = store_codec::decode_goal(domain, std::move(key), goals.getColumn(5).getString(),
                                           Provenance{goals.getColumn(6).getString(), goals.getColumn(7).getString()});
      if (!goal) return located(goal.error());
      news.goals.push_back(std::move(*goal));
      news.goal_robots.push_back(goals.getColumn(8).getString());
    }
    SQLite::Statement rules(*db_, sql::new_rules(version_));
    rules.bind(1, last_rule_id_);
    while (rules.executeStep()) {
      last_rule_id_ = std::max(last_rule_id_, rules.getColumn(0).getInt64());
      auto rule = store_codec::decode_rule(domain, rules.getColumn(1).getString(),
                                           Provenance{rules.getColumn(2).getString(), rules.getColumn(3).getString()});
      if (!rule) return located(rule.error());
      news.rules.push_back(std::move(*rule));
    }
    // Of this very snapshot: a commit after it changes the version again.
    data_version_ = now;
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
  return news;
}

Result<std::vector<std::string>> SqliteStore::households() const {
  std::vector<std::string> out;
  try {
    SQLite::Statement names(*db_, sql::households_query(version_));
    while (names.executeStep()) out.push_back(names.getColumn(0).getString());
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
  return out;
}

Result<Knowledge> SqliteStore::load(const Domain& domain) const {
  Knowledge knowledge;
  // The text of a column, or the entry's error.
  auto text = [](const SQLite::Column& column, const std::string& entry) -> Result<std::string> {
    if (!column.isText()) return tl::unexpected(store_codec::unreadable(entry, "not text"));
    return column.getString();
  };
  auto located = [&](const Error& error) { return tl::unexpected(prefix_error(error, path_.string())); };
  try {
    // One read transaction: a consistent snapshot while writers go on.
    SQLite::Transaction snapshot(*db_, SQLite::TransactionBehavior::DEFERRED);
    // A version 1 store holds the default household's goals and tasks alone.
    const bool v1 = version_ == 1;
    SQLite::Statement tasks(*db_, v1 ? sql::kTasksV1 : sql::kTasks);
    tasks.bind(1, household_);
    while (tasks.executeStep()) {
      const std::string name = tasks.getColumn(0).getString();
      auto structure = text(tasks.getColumn(1), store_codec::task_entry(name));
      if (!structure) return located(structure.error());
      auto task = store_codec::decode_task(name, *structure);
      if (!task) return located(task.error());
      knowledge.tasks.push_back(std::move(*task));
    }
    // A goal's row from column `first` on: task, subtask, category, place,
    // literals, object, source.
    auto goal_at = [&](SQLite::Statement& row, int first) -> Result<GoalKnowledge> {
      GoalKey key{row.getColumn(first).getString(), row.getColumn(first + 1).getString(),
                  row.getColumn(first + 2).getString(), row.getColumn(first + 3).getString()};
      auto literals = text(row.getColumn(first + 4), store_codec::goal_entry(key));
      if (!literals) return tl::unexpected(literals.error());
      return store_codec::decode_goal(
          domain, std::move(key), *literals,
          Provenance{row.getColumn(first + 5).getString(), row.getColumn(first + 6).getString()});
    };
    SQLite::Statement goals(*db_, v1 ? sql::kGoalsV1 : sql::kGoals);
    goals.bind(1, household_);
    while (goals.executeStep()) {
      auto goal = goal_at(goals, 0);
      if (!goal) return located(goal.error());
      knowledge.goals.add(std::move(*goal));
    }
    if (!v1) {
      SQLite::Statement fleet(*db_, sql::kFleetGoals);
      fleet.bind(1, household_);
      while (fleet.executeStep()) {
        auto goal = goal_at(fleet, 1);
        // Another world's goal (a predicate this domain lacks) is no prior here.
        if (!goal && goal.error().code == ErrorCode::kFailedPrecondition) continue;
        if (!goal) return located(goal.error());
        knowledge.fleet.add(fleet.getColumn(0).getString(), std::move(*goal));
      }
    }
    SQLite::Statement rules(*db_, sql::kRules);
    while (rules.executeStep()) {
      auto body = text(rules.getColumn(0), store_codec::kRuleEntry);
      if (!body) return located(body.error());
      auto rule = store_codec::decode_rule(domain, *body,
                                           Provenance{rules.getColumn(1).getString(), rules.getColumn(2).getString()});
      if (!rule) return located(rule.error());
      knowledge.rules.add(domain, std::move(*rule));
    }
    // Stores before version 3 (read as they are) have no class rules.
    if (version_ >= 3) {
      for (auto [query, into] : {std::pair{sql::kClassRules, &knowledge.class_rules},
                                 std::pair{sql::kForgottenRules, &knowledge.forgotten_rules}}) {
        SQLite::Statement rows(*db_, query);
        rows.bind(1, household_);
        while (rows.executeStep()) {
          auto body = text(rows.getColumn(0), store_codec::kClassRuleEntry);
          if (!body) return located(body.error());
          auto rule = store_codec::decode_class_rule(domain, *body);
          if (!rule) return located(rule.error());
          into->add(std::move(*rule));
        }
      }
    }
    mark_seen();
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
  return knowledge;
}

}  // namespace

Result<std::unique_ptr<StoreEngine>> open_sqlite_store(const std::filesystem::path& path, StoreAccess access,
                                                       const std::string& household, const std::string& robot) {
  const bool read_only = access == StoreAccess::kReadOnly;
  // 1. The file, created if absent (unless read-only), and its lock. A new
  // store is created whole under another name and moved into place
  // (store_creation.h), so that a killed process never leaves an empty or
  // half-made store; one that appeared meanwhile is opened instead.
  if (!read_only) remove_abandoned_creations(path);
  int fd = -1;
  for (int attempt = 0; attempt < 3; ++attempt) {
    fd = open_retrying(path, read_only ? O_RDONLY | O_CLOEXEC : O_RDWR | O_CLOEXEC);
    if (fd >= 0 || errno != ENOENT || read_only || attempt == 2) break;
    if (auto created = create_store_file(path); !created) return tl::unexpected(created.error());
  }
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT && read_only) return make_error(ErrorCode::kNotFound, path.string() + ": no such knowledge store");
    if (error == EISDIR)
      return make_error(ErrorCode::kInvalidInput, path.string() + ": is a directory, not a knowledge store");
    return make_error(ErrorCode::kIo, path.string() + ": cannot " + (read_only ? "open" : "open or create") +
                                          " the knowledge store: " + std::strerror(error));
  }
  FileDescriptor lock(fd);
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    return make_error(ErrorCode::kIo, path.string() + ": cannot read the knowledge store: " + std::strerror(errno));
  if (S_ISDIR(info.st_mode))
    return make_error(ErrorCode::kInvalidInput, path.string() + ": is a directory, not a knowledge store");
  if (!S_ISREG(info.st_mode)) return not_a_store(path, "not a regular file");
  const int locked = flock_retrying(fd, (access == StoreAccess::kFresh ? LOCK_EX : LOCK_SH) | LOCK_NB);
  if (locked != 0) {
    if (errno == EWOULDBLOCK)
      return make_error(ErrorCode::kIo,
                        path.string() + ": the knowledge store is in use by another process" +
                            (access == StoreAccess::kFresh
                                 ? "; an experiment starts a store over only when nobody else has it open. Wait "
                                   "for the other process, or choose another --knowledge-out directory."
                                 : ", which is starting it over (experiment --knowledge-out); wait until it finishes."));
    return make_error(ErrorCode::kIo, path.string() + ": cannot lock the knowledge store: " + std::strerror(errno));
  }

  // 2. What the file holds: nothing (a new store, unless read-only), or an
  // SQLite database. SQLite itself would take any file of up to 1 byte for
  // an empty database and overwrite it.
  if (info.st_size == 0 && read_only) return not_a_store(path, "the file is empty");
  if (info.st_size > 0) {
    constexpr std::string_view kHeader("SQLite format 3\0", 16);
    char head[16] = {};
    ssize_t n = ::pread(fd, head, sizeof head, 0);
    if (n != static_cast<ssize_t>(sizeof head) || std::string_view(head, sizeof head) != kHeader)
      return not_a_store(path, "not an SQLite database");
  }

  // 3. SQLite: a rollback journal with full syncs, so a transaction that
  // returned is on disk and a killed writer leaves a journal SQLite rolls
  // back; quick_check; the schema.
  try {
    auto connect = [&](int flags) {
      auto db = std::make_unique<SQLite::Database>(path.string(), flags);
      db->exec("PRAGMA busy_timeout = " + std::to_string(kBusyTimeoutMs));
      return db;
    };
    std::unique_ptr<SQLite::Database> db;
    if (read_only) {
      db = connect(SQLite::OPEN_READONLY);
      try {
        if (auto status = quick_check(*db, path); !status) return tl::unexpected(status.error());
      } catch (const SQLite::Exception& e) {
        if (e.getExtendedErrorCode() != SQLITE_READONLY_ROLLBACK) throw;
        // A killed writer left a hot journal, which only a writer can roll
        // back: let one do it, then read as before.
        db.reset();
        connect(SQLite::OPEN_READWRITE)->exec("SELECT count(*) FROM sqlite_master");
        db = connect(SQLite::OPEN_READONLY);
        if (auto status = quick_check(*db, path); !status) return tl::unexpected(status.error());
      }
    } else {
      db = connect(SQLite::OPEN_READWRITE);
      db->exec("PRAGMA journal_mode = DELETE");
      db->exec("PRAGMA synchronous = FULL");
      if (auto status = quick_check(*db, path); !status) return tl::unexpected(status.error());
    }
    auto version = check_or_create_schema(*db, path, !read_only);
    if (!version) return tl::unexpected(version.error());
    if (access == StoreAccess::kFresh) {
      SQLite::Transaction transaction(*db, SQLite::TransactionBehavior::IMMEDIATE);
      for (const char* statement : sql::kStartOver) db->exec(statement);
      transaction.commit();
    }
    auto store = std::make_unique<SqliteStore>(path, household, robot, *version, std::move(lock), std::move(db));
    store->mark_seen();
    return std::unique_ptr<StoreEngine>(std::move(store));
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path, e));
  }
}

}  // namespace apprentice
