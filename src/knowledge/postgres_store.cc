#include "knowledge/postgres_store.h"

#include <libpq-fe.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <optional>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "knowledge/store_location.h"
#include "knowledge/store_codec.h"
#include "knowledge/store_creation.h"
#include "knowledge/store_sql.h"

namespace apprentice {

namespace {

// Advisory lock keys: (class, hash of the schema). The class spells "appr".
constexpr int kLockClass = 0x61707072;
// Held inside the transaction that creates a store's tables.
constexpr int kCreationLockClass = 0x61707073;
// How long to wait after a lost connection before each new try: about 10 s
// in all, longer than a PostgreSQL restart takes.
constexpr int kReconnectDelaysMs[] = {100, 250, 500, 1000, 2000, 2000, 2000, 2000};
// How long to wait before each new try of the store's lock, about 1.5 s in
// all: a connection closed a moment ago (by this process or one that just
// ended) keeps its lock until its server process has finished, which
// PQfinish does not wait for.
constexpr int kLockRetryDelaysMs[] = {20, 50, 100, 200, 400, 700};
// How many times one call makes its connection again before it gives up.
constexpr int kMostReconnects = 3;
// The channel every save notifies, with a JSON array for payload: the
// schema, then "goal" and the household and key, or "rule" and its
// signature (news()).
constexpr const char* kChannel = "apprentice_knowledge";

using Texts = std::vector<std::string>;

struct ResultDeleter {
  void operator()(PGresult* r) const { PQclear(r); }
};
using PgResult = std::unique_ptr<PGresult, ResultDeleter>;
struct ConnectionDeleter {
  void operator()(PGconn* c) const { PQfinish(c); }
};
using PgConnection = std::unique_ptr<PGconn, ConnectionDeleter>;

bool succeeded(const PGresult* r) {
  const ExecStatusType status = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
  return status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK;
}

// The first line of libpq's message, without its "ERROR:  " or "FATAL:  ",
// with `secret` (the password) cut out wherever it appears.
std::string one_line(const char* message, const std::string& secret) {
  std::string text = message ? message : "";
  while (!text.empty() && (text.front() == '\n' || text.front() == ' ')) text.erase(0, 1);
  if (auto end = text.find('\n'); end != std::string::npos) text.resize(end);
  for (const char* prefix : {"ERROR:  ", "FATAL:  "})
    for (auto at = text.find(prefix); at != std::string::npos; at = text.find(prefix)) text.erase(at, std::strlen(prefix));
  if (secret.size() >= 3)
    for (auto at = text.find(secret); at != std::string::npos; at = text.find(secret, at))
      text.replace(at, secret.size(), "***");
  return text.empty() ? "no reason given" : text;
}

// What a failed statement means to the user, by its SQLSTATE.
Error statement_error(const std::string& where, const PGresult* r, PGconn* connection, const std::string& secret) {
  const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
  const std::string code = state ? state : "";
  const std::string why = one_line(r ? PQresultErrorMessage(r) : PQerrorMessage(connection), secret);
  if (code == "42P01" || code == "42703")
    return Error{ErrorCode::kDataLoss, where + ": the knowledge store is damaged: a table or column is missing (" + why + ")"};
  if (code == "53100") return Error{ErrorCode::kIo, where + ": the server's disk is full (" + why + ")"};
  if (code == "25006") return Error{ErrorCode::kIo, where + ": the database is read-only (" + why + ")"};
  if (code.rfind("08", 0) == 0 || (!state && PQstatus(connection) == CONNECTION_BAD))
    return Error{ErrorCode::kIo, where + ": the connection to the PostgreSQL server was lost and could not be made again (" + why + ")"};
  return Error{ErrorCode::kIo, where + ": " + why};
}

class PostgresStore final : public store_sql::SqlEngine {
 public:
  PostgresStore(std::string url, std::string where, std::string secret, StoreAccess access, std::string household,
                std::string robot)
      : SqlEngine(std::move(household), std::move(robot)), url_(std::move(url)), where_(std::move(where)),
        secret_(std::move(secret)), access_(access) {}

  Status connect();
  Status check_or_create_schema();
  Status start_over();

  Status save_goal(const GoalKnowledge& goal) override;
  Status save_rule(const Domain& domain, const Rule& rule) override;
  Status save_task(const TaskKnowledge& task) override;
  Result<Knowledge> load(const Domain& domain) const override;
  Result<std::vector<std::string>> households() const override;
  Status save_class_rule(const ClassRule& rule) override;
  Status forget_class_rule(const ClassRule& rule) override;
  Result<StoreNews> news(const Domain& domain) override;

 private:
  // The goal under `key` of this household, if it is still stored, with
  // the robot that saved it.
  Result<std::optional<std::pair<GoalKnowledge, std::string>>> stored_goal(const Domain& domain, const GoalKey& key) const;
  Result<std::optional<Rule>> stored_rule(const Domain& domain, const std::string& signature) const;
  PgResult run(const std::string& sql, const Texts& values = {}) const;
  // Runs `shared`, SQL of store_sql.h, its `?` numbered.
  PgResult run_shared(std::string_view shared, const Texts& values = {}) const {
    return run(store_sql::numbered_placeholders(shared), values);
  }
  // Runs `sql`, which must succeed, or gives its error.
  Status must(const std::string& sql, const Texts& values = {}) const;
  Status take_session_lock() const;
  // After a failure: whether the connection was lost and has been made again.
  bool reconnected() const;
  // One write, retried on a connection made again; `shared` is written
  // with store_sql.h's `?` placeholders.
  template <typename Parameters>
  Status write(std::string_view shared, Parameters parameters);
  Status execute(const char* sql, const Texts& values) override {
    return write(sql, [&] { return values; });
  }
  Result<Knowledge> load_once(const Domain& domain) const;
  // meta's schema version, or the store's error.
  Result<std::string> read_version() const;
  // Runs `body` in one transaction holding the creation lock (creating
  // the tables, migrating them), rolled back if it fails.
  template <typename Body>
  Status under_creation_lock(Body body);
  // Migrates a store of an older version, in one transaction that reads
  // the version again under the creation lock.
  Status migrate();
  Status check_schema();

  // The URL as given (it may hold the password): for libpq only.
  std::string url_;
  // The store's name in messages: the URL without its password.
  std::string where_;
  std::string secret_;
  StoreAccess access_;
  // The store's schema version: kKnowledgeSchemaVersion, or an older one a
  // reader reads as it is.
  int version_ = kKnowledgeSchemaVersion;
  // The connection's current schema, which notifications name.
  std::string schema_;
  PgConnection connection_;
};

PgResult PostgresStore::run(const std::string& sql, const Texts& values) const {
  // Without parameters, the simple protocol: `sql` may be several statements.
  if (values.empty()) return PgResult(PQexec(connection_.get(), sql.c_str()));
  std::vector<const char*> pointers;
  for (const std::string& v : values) pointers.push_back(v.c_str());
  return PgResult(PQexecParams(connection_.get(), sql.c_str(), static_cast<int>(values.size()), nullptr,
                               pointers.data(), nullptr, nullptr, 0));
}

Status PostgresStore::must(const std::string& sql, const Texts& values) const {
  PgResult r = run(sql, values);
  if (succeeded(r.get())) return {};
  return tl::unexpected(statement_error(where_, r.get(), connection_.get(), secret_));
}

Status PostgresStore::take_session_lock() const {
  // Every save notifies kChannel (news()); a reader listens too.
  if (auto s = must(std::string("LISTEN ") + kChannel); !s) return s;
  // Durable once a statement returns, whatever the server's default; a
  // reader writes nothing.
  if (auto s = must("SET synchronous_commit = on"); !s) return s;
  if (access_ == StoreAccess::kReadOnly)
    if (auto s = must("SET default_transaction_read_only = on"); !s) return s;
  const bool exclusive = access_ == StoreAccess::kFresh;
  const std::string try_lock = std::string("SELECT ") +
                               (exclusive ? "pg_try_advisory_lock" : "pg_try_advisory_lock_shared") +
                               "($1::int, hashtext(coalesce(current_schema(), '')))";
  for (std::size_t attempt = 0;; ++attempt) {
    PgResult locked = run(try_lock, {std::to_string(kLockClass)});
    if (!succeeded(locked.get())) return tl::unexpected(statement_error(where_, locked.get(), connection_.get(), secret_));
    if (std::string(PQgetvalue(locked.get(), 0, 0)) == "t") return {};
    if (attempt == std::size(kLockRetryDelaysMs)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(kLockRetryDelaysMs[attempt]));
  }
  return make_error(ErrorCode::kIo,
                    where_ + ": the knowledge store is in use by another process" +
                        (exclusive ? "; an experiment starts a store over only when nobody else has it open. Wait for "
                                     "the other process, or choose another store."
                                   : ", which is starting it over (experiment --knowledge-out); wait until it finishes."));
}

Status PostgresStore::connect() {
  // connect_timeout first, so that one in the URL overrides it.
  const char* keys[] = {"connect_timeout", "fallback_application_name", "dbname", nullptr};
  const char* values[] = {"5", "apprentice", url_.c_str(), nullptr};
  connection_.reset(PQconnectdbParams(keys, values, 1));
  if (!connection_) return make_error(ErrorCode::kIo, where_ + ": out of memory connecting to PostgreSQL");
  if (PQstatus(connection_.get()) != CONNECTION_OK) {
    const char* host = PQhost(connection_.get());
    const char* port = PQport(connection_.get());
    const char* db = PQdb(connection_.get());
    const std::string server = std::string(host ? host : "") + ":" + (port ? port : "") + "/" + (db ? db : "");
    const std::string why = one_line(PQerrorMessage(connection_.get()), secret_);
    if (why.find("database \"") != std::string::npos && why.find("does not exist") != std::string::npos)
      return make_error(ErrorCode::kNotFound, server + ": no such database on the PostgreSQL server (" + why +
                                                  "); create it first, for example with createdb");
    return make_error(ErrorCode::kIo, server + ": cannot connect to the PostgreSQL server of the knowledge store (" + why + ")");
  }
  PgResult schema = run("SELECT coalesce(current_schema(), '')");
  if (!succeeded(schema.get())) return tl::unexpected(statement_error(where_, schema.get(), connection_.get(), secret_));
  schema_ = PQgetvalue(schema.get(), 0, 0);
  return take_session_lock();
}

bool PostgresStore::reconnected() const {
  if (PQstatus(connection_.get()) != CONNECTION_BAD) return false;
  for (int delay : kReconnectDelaysMs) {
    std::this_thread::sleep_for(std::chrono::milliseconds(delay));
    PQreset(connection_.get());
    if (PQstatus(connection_.get()) == CONNECTION_OK) return take_session_lock().has_value();
  }
  return false;
}

namespace sql = store_sql;

// The steps from each older schema version to the next, in order, as
// PostgreSQL takes them (several statements each): entry i goes from
// version i + kOldestMigratedSchemaVersion. Version 1 to 2: goals and tasks
// gain a household, part of their keys; what there was is the default
// household's (the constraints version 1 made have PostgreSQL's default
// names). Version 2 to 3: each household's class rules with their
// evidence, and the rules it forgot. Version 3 to 4: goals and rules name
// the robot that saved them.
std::string migration(int from_version) {
  std::string steps;
  auto join = [&](const auto& statements) {
    for (const auto& statement : statements) steps += std::string(statement) + ";";
  };
  switch (from_version) {
    case 1:
      return "ALTER TABLE goals ADD COLUMN household TEXT NOT NULL DEFAULT 'default';"
             "ALTER TABLE goals ALTER COLUMN household DROP DEFAULT;"
             "ALTER TABLE goals DROP CONSTRAINT goals_task_subtask_category_place_key;"
             "ALTER TABLE goals ADD UNIQUE(household, task, subtask, category, place);"
             "ALTER TABLE tasks ADD COLUMN household TEXT NOT NULL DEFAULT 'default';"
             "ALTER TABLE tasks ALTER COLUMN household DROP DEFAULT;"
             "ALTER TABLE tasks DROP CONSTRAINT tasks_pkey;"
             "ALTER TABLE tasks ADD PRIMARY KEY(household, name);";
    case 2: join(sql::class_rules_tables(sql::kPostgresId)); return steps;
    default: join(sql::kMigration3To4); return steps;
  }
}
static_assert(kKnowledgeSchemaVersion == 4, "a new schema version needs its step in migration()");

Status PostgresStore::check_or_create_schema() {
  auto tables = [&]() -> Result<std::pair<bool, long>> {
    PgResult r = run(
        "SELECT count(*) FILTER (WHERE tablename = 'meta'), count(*) FROM pg_catalog.pg_tables "
        "WHERE schemaname = current_schema()");
    if (!succeeded(r.get())) return tl::unexpected(statement_error(where_, r.get(), connection_.get(), secret_));
    return std::pair{std::string(PQgetvalue(r.get(), 0, 0)) != "0", std::strtol(PQgetvalue(r.get(), 0, 1), nullptr, 10)};
  };
  auto found = tables();
  if (!found) return tl::unexpected(found.error());
  auto foreign = [&] {
    return make_error(ErrorCode::kFailedPrecondition,
                      where_ + " is a PostgreSQL database of another program, not an apprentice knowledge store");
  };
  if (!found->first && found->second > 0) return foreign();
  if (!found->first && access_ == StoreAccess::kReadOnly)
    return make_error(ErrorCode::kNotFound, where_ + ": no such knowledge store (the database holds no tables)");
  if (!found->first) {
    auto created = under_creation_lock([&]() -> Status {
      auto again = tables();
      if (!again) return tl::unexpected(again.error());
      if (again->first) return {};
      if (again->second > 0) return foreign();
      for (const std::string& table : sql::schema(sql::kPostgresId))
        if (auto s = must(table); !s) return s;
      return must(sql::numbered_placeholders(sql::kInsertMeta),
                  {kKnowledgeFormatName, std::to_string(kKnowledgeSchemaVersion)});
    });
    if (!created) return created;
  }
  return check_schema();
}

Result<std::string> PostgresStore::read_version() const {
  PgResult meta = run(sql::kReadMeta);
  if (!succeeded(meta.get())) return tl::unexpected(statement_error(where_, meta.get(), connection_.get(), secret_));
  std::string format, version;
  for (int row = 0; row < PQntuples(meta.get()); ++row) {
    const std::string key = PQgetvalue(meta.get(), row, 0);
    if (key == "format") format = PQgetvalue(meta.get(), row, 1);
    if (key == "schema_version") version = PQgetvalue(meta.get(), row, 1);
  }
  if (format != kKnowledgeFormatName)
    return make_error(ErrorCode::kFailedPrecondition, where_ + " is not an apprentice knowledge store");
  if (sql::version_number(version) == 0)
    return make_error(ErrorCode::kFailedPrecondition, sql::other_version(where_, version));
  return version;
}

template <typename Body>
Status PostgresStore::under_creation_lock(Body body) {
  if (auto s = must("BEGIN"); !s) return s;
  Status done = must("SELECT pg_advisory_xact_lock($1::int, hashtext(coalesce(current_schema(), '')))",
                     {std::to_string(kCreationLockClass)});
  if (done) done = body();
  if (!done) {
    (void)run("ROLLBACK");
    return done;
  }
  return must("COMMIT");
}

Status PostgresStore::migrate() {
  return under_creation_lock([&]() -> Status {
    auto again = read_version();
    if (!again) return tl::unexpected(again.error());
    for (int v = sql::version_number(*again); v < kKnowledgeSchemaVersion; ++v)
      if (auto s = must(migration(v)); !s) return s;
    return must(sql::numbered_placeholders(sql::kSetVersion), {std::to_string(kKnowledgeSchemaVersion)});
  });
}

Status PostgresStore::check_schema() {
  auto version = read_version();
  if (!version) return tl::unexpected(version.error());
  version_ = sql::version_number(*version);
  if (version_ < kKnowledgeSchemaVersion && access_ != StoreAccess::kReadOnly) {
    if (auto s = migrate(); !s) return s;
    version_ = kKnowledgeSchemaVersion;
  }
  const bool v1 = version_ == 1;
  std::vector<const char*> queries{v1 ? sql::kTasksV1 : sql::kTasks, v1 ? sql::kGoalsV1 : sql::kGoals, sql::kRules};
  if (version_ >= 3) {
    queries.push_back(sql::kClassRules);
    queries.push_back(sql::kForgottenRules);
  }
  for (const char* query : queries) {
    PgResult r = run_shared(std::string(query) + " LIMIT 0", query == sql::kRules ? Texts{} : Texts{household_});
    if (succeeded(r.get())) continue;
    Error e = statement_error(where_, r.get(), connection_.get(), secret_);
    return tl::unexpected(e);
  }
  return {};
}

Status PostgresStore::start_over() {
  std::string all = "BEGIN;";
  for (const char* statement : sql::kStartOver) all += std::string(statement) + ";";
  return must(all + "COMMIT");
}

template <typename Parameters>
Status PostgresStore::write(std::string_view shared, Parameters parameters) {
  const std::string statement = sql::numbered_placeholders(shared);
  const Texts values = parameters();
  for (int attempt = 0;; ++attempt) {
    PgResult r = run(statement, values);
    if (succeeded(r.get())) return {};
    Error e = statement_error(where_, r.get(), connection_.get(), secret_);
    if (attempt == kMostReconnects || !reconnected()) return tl::unexpected(e);
  }
}

// What the engines' dialects cannot share (store_sql.h): PostgreSQL's
// upserts, which give a replaced goal a new id, as SQLite's INSERT OR
// REPLACE does, and notify in the save's own transaction (news()).
Status PostgresStore::save_goal(const GoalKnowledge& goal) {
  // A goal saved again under its key is replaced and moves to the end.
  return write(
      "WITH saved AS (INSERT INTO goals(household, task, subtask, category, place, literals, object, source, robot) "
      "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9) "
      "ON CONFLICT (household, task, subtask, category, place) DO UPDATE SET literals = EXCLUDED.literals, object = "
      "EXCLUDED.object, source = EXCLUDED.source, robot = EXCLUDED.robot, "
      "id = nextval(pg_get_serial_sequence('goals', 'id')) RETURNING 1) "
      "SELECT pg_notify('apprentice_knowledge', json_build_array(current_schema(), 'goal', $1::text, $2::text, $3::text, "
      "$4::text, $5::text)::text) FROM saved",
      [&] {
        return Texts{household_, goal.key.task, goal.key.subtask, goal.key.category, goal.key.place,
                     store_codec::encode_goal_literals(goal), goal.provenance.object, goal.provenance.source, robot_};
      });
}

Status PostgresStore::save_rule(const Domain& domain, const Rule& rule) {
  // Notifies only when the rule is new.
  return write("WITH saved AS (INSERT INTO rules(signature, body, object, source, robot) VALUES ($1, $2, $3, $4, $5) "
               "ON CONFLICT (signature) DO NOTHING RETURNING 1) "
               "SELECT pg_notify('apprentice_knowledge', json_build_array(current_schema(), 'rule', $1::text)::text) "
               "FROM saved",
               [&] {
                 return Texts{rule_signature(domain, rule), store_codec::encode_rule(domain, rule), rule.provenance.object,
                              rule.provenance.source, robot_};
               });
}

Status PostgresStore::save_task(const TaskKnowledge& task) {
  return write("INSERT INTO tasks(household, name, structure) VALUES ($1, $2, $3) ON CONFLICT (household, name) DO UPDATE "
               "SET structure = EXCLUDED.structure",
               [&] { return Texts{household_, task.name, store_codec::encode_subtasks(task)}; });
}

Result<std::optional<std::pair<GoalKnowledge, std::string>>> PostgresStore::stored_goal(const Domain& domain,
                                                                                        const GoalKey& key) const {
  PgResult r = run_shared(sql::goal_by_key(version_), {household_, key.task, key.subtask, key.category, key.place});
  if (!succeeded(r.get())) return tl::unexpected(statement_error(where_, r.get(), connection_.get(), secret_));
  if (PQntuples(r.get()) == 0) return std::nullopt;
  auto goal = store_codec::decode_goal(domain, key, PQgetvalue(r.get(), 0, 0),
                                       Provenance{PQgetvalue(r.get(), 0, 1), PQgetvalue(r.get(), 0, 2)});
  if (!goal) return tl::unexpected(prefix_error(goal.error(), where_));
  return std::optional<std::pair<GoalKnowledge, std::string>>(std::in_place, std::move(*goal), PQgetvalue(r.get(), 0, 3));
}

Result<std::optional<Rule>> PostgresStore::stored_rule(const Domain& domain, const std::string& signature) const {
  PgResult r = run_shared(sql::rule_by_signature(version_), {signature});
  if (!succeeded(r.get())) return tl::unexpected(statement_error(where_, r.get(), connection_.get(), secret_));
  if (PQntuples(r.get()) == 0) return std::nullopt;
  auto rule = store_codec::decode_rule(domain, PQgetvalue(r.get(), 0, 0),
                                       Provenance{PQgetvalue(r.get(), 0, 1), PQgetvalue(r.get(), 0, 2)});
  if (!rule) return tl::unexpected(prefix_error(rule.error(), where_));
  return std::optional<Rule>(std::move(*rule));
}

Result<StoreNews> PostgresStore::news(const Domain& domain) {
  StoreNews news;
  // Reads what the server sent without waiting; a lost connection is made
  // again (LISTEN with it) by the next save or load, and what was notified
  // meanwhile is in what that load reads.
  if (PQconsumeInput(connection_.get()) == 0) return news;
  std::vector<GoalKey> goals;
  std::vector<std::string> rules;
  const int own = PQbackendPID(connection_.get());
  while (PGnotify* raw = PQnotifies(connection_.get())) {
    std::unique_ptr<PGnotify, decltype(&PQfreemem)> notice(raw, &PQfreemem);
    if (notice->be_pid == own || std::strcmp(notice->relname, kChannel) != 0) continue;
    const nlohmann::json said = nlohmann::json::parse(notice->extra, nullptr, false);
    auto text = [&](std::size_t i) {
      return said.is_array() && i < said.size() && said[i].is_string() ? said[i].get<std::string>() : std::string();
    };
    if (text(0) != schema_) continue;
    if (text(1) == "goal" && text(2) == household_) {
      GoalKey key{text(3), text(4), text(5), text(6)};
      if (std::find(goals.begin(), goals.end(), key) == goals.end()) goals.push_back(std::move(key));
    } else if (text(1) == "rule" && std::find(rules.begin(), rules.end(), text(2)) == rules.end()) {
      rules.push_back(text(2));
    }
  }
  for (const GoalKey& key : goals) {
    auto goal = stored_goal(domain, key);
    if (!goal) return tl::unexpected(goal.error());
    if (!*goal) continue;
    news.goals.push_back(std::move((*goal)->first));
    news.goal_robots.push_back(std::move((*goal)->second));
  }
  for (const std::string& signature : rules) {
    auto rule = stored_rule(domain, signature);
    if (!rule) return tl::unexpected(rule.error());
    if (*rule) news.rules.push_back(std::move(**rule));
  }
  return news;
}

Result<std::vector<std::string>> PostgresStore::households() const {
  for (int attempt = 0;; ++attempt) {
    PgResult r = run(sql::households_query(version_));
    if (succeeded(r.get())) {
      std::vector<std::string> out;
      for (int row = 0; row < PQntuples(r.get()); ++row) out.emplace_back(PQgetvalue(r.get(), row, 0));
      return out;
    }
    Error e = statement_error(where_, r.get(), connection_.get(), secret_);
    if (attempt == kMostReconnects || !reconnected()) return tl::unexpected(e);
  }
}

Status PostgresStore::save_class_rule(const ClassRule& rule) {
  // One statement, so one transaction: the rule, off the forgotten list.
  // A rule saved again under its key is replaced and moves to the end.
  return write(
      "WITH unforgotten AS (DELETE FROM forgotten_rules WHERE household = $1 AND key = $2) "
      "INSERT INTO class_rules(household, key, body, source) VALUES ($1, $2, $3, $4) ON CONFLICT (household, key) "
      "DO UPDATE SET body = EXCLUDED.body, source = EXCLUDED.source, "
      "id = nextval(pg_get_serial_sequence('class_rules', 'id'))",
      [&] {
        return Texts{household_, class_rule_key(rule), store_codec::encode_class_rule(rule),
                     std::string(rule_source_name(rule.source))};
      });
}

Status PostgresStore::forget_class_rule(const ClassRule& rule) {
  return write(
      "WITH removed AS (DELETE FROM class_rules WHERE household = $1 AND key = $2) "
      "INSERT INTO forgotten_rules(household, key, body) VALUES ($1, $2, $3) ON CONFLICT (household, key) "
      "DO UPDATE SET body = EXCLUDED.body",
      [&] { return Texts{household_, class_rule_key(rule), store_codec::encode_class_rule(rule)}; });
}

Result<Knowledge> PostgresStore::load(const Domain& domain) const {
  for (int attempt = 0;; ++attempt) {
    auto knowledge = load_once(domain);
    if (knowledge || knowledge.error().code != ErrorCode::kIo || attempt == kMostReconnects || !reconnected())
      return knowledge;
  }
}

Result<Knowledge> PostgresStore::load_once(const Domain& domain) const {
  auto located = [&](const Error& error) { return tl::unexpected(prefix_error(error, where_)); };
  auto failed = [&](const PgResult& r) {
    Error e = statement_error(where_, r.get(), connection_.get(), secret_);
    (void)run("ROLLBACK");
    return tl::unexpected(e);
  };
  // The text of a cell, or the entry's error.
  auto text = [](const PGresult* r, int row, int column, const std::string& entry) -> Result<std::string> {
    if (PQgetisnull(r, row, column)) return tl::unexpected(store_codec::unreadable(entry, "no value"));
    return std::string(PQgetvalue(r, row, column), static_cast<std::size_t>(PQgetlength(r, row, column)));
  };
  // One transaction: a consistent snapshot while writers go on.
  if (PgResult begin = run("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY"); !succeeded(begin.get())) return failed(begin);
  // A version 1 store holds the default household's goals and tasks alone.
  const bool v1 = version_ == 1;
  const Texts household{household_};
  PgResult tasks = run_shared(v1 ? sql::kTasksV1 : sql::kTasks, household);
  if (!succeeded(tasks.get())) return failed(tasks);
  PgResult goals = run_shared(v1 ? sql::kGoalsV1 : sql::kGoals, household);
  if (!succeeded(goals.get())) return failed(goals);
  PgResult rules = run(sql::kRules);
  if (!succeeded(rules.get())) return failed(rules);
  PgResult fleet;
  if (!v1) {
    fleet = run_shared(sql::kFleetGoals, household);
    if (!succeeded(fleet.get())) return failed(fleet);
  }
  // Stores before version 3 (read as they are) have no class rules.
  PgResult class_rules, forgotten_rules;
  if (version_ >= 3) {
    class_rules = run_shared(sql::kClassRules, household);
    if (!succeeded(class_rules.get())) return failed(class_rules);
    forgotten_rules = run_shared(sql::kForgottenRules, household);
    if (!succeeded(forgotten_rules.get())) return failed(forgotten_rules);
  }
  (void)run("COMMIT");
  Knowledge knowledge;
  for (int row = 0; row < PQntuples(tasks.get()); ++row) {
    const std::string name = PQgetvalue(tasks.get(), row, 0);
    auto structure = text(tasks.get(), row, 1, store_codec::task_entry(name));
    if (!structure) return located(structure.error());
    auto task = store_codec::decode_task(name, *structure);
    if (!task) return located(task.error());
    knowledge.tasks.push_back(std::move(*task));
  }
  const PGresult* g = goals.get();
  for (int row = 0; row < PQntuples(g); ++row) {
    GoalKey key{PQgetvalue(g, row, 0), PQgetvalue(g, row, 1), PQgetvalue(g, row, 2), PQgetvalue(g, row, 3)};
    auto literals = text(g, row, 4, store_codec::goal_entry(key));
    if (!literals) return located(literals.error());
    auto goal = store_codec::decode_goal(domain, std::move(key), *literals, Provenance{PQgetvalue(g, row, 5), PQgetvalue(g, row, 6)});
    if (!goal) return located(goal.error());
    knowledge.goals.add(std::move(*goal));
  }
  for (int row = 0; fleet && row < PQntuples(fleet.get()); ++row) {
    const PGresult* f = fleet.get();
    GoalKey key{PQgetvalue(f, row, 1), PQgetvalue(f, row, 2), PQgetvalue(f, row, 3), PQgetvalue(f, row, 4)};
    auto literals = text(f, row, 5, store_codec::goal_entry(key));
    if (!literals) return located(literals.error());
    auto goal = store_codec::decode_goal(domain, std::move(key), *literals, Provenance{PQgetvalue(f, row, 6), PQgetvalue(f, row, 7)});
    // Another world's goal (a predicate this domain lacks) is no prior here.
    if (!goal && goal.error().code == ErrorCode::kFailedPrecondition) continue;
    if (!goal) return located(goal.error());
    knowledge.fleet.add(PQgetvalue(f, row, 0), std::move(*goal));
  }
  const PGresult* r = rules.get();
  for (int row = 0; row < PQntuples(r); ++row) {
    auto body = text(r, row, 0, store_codec::kRuleEntry);
    if (!body) return located(body.error());
    auto rule = store_codec::decode_rule(domain, *body, Provenance{PQgetvalue(r, row, 1), PQgetvalue(r, row, 2)});
    if (!rule) return located(rule.error());
    knowledge.rules.add(domain, std::move(*rule));
  }
  for (auto [rows, into] : {std::pair{class_rules.get(), &knowledge.class_rules},
                            std::pair{forgotten_rules.get(), &knowledge.forgotten_rules}}) {
    if (rows == nullptr) continue;
    for (int row = 0; row < PQntuples(rows); ++row) {
      auto body = text(rows, row, 0, store_codec::kClassRuleEntry);
      if (!body) return located(body.error());
      auto rule = store_codec::decode_class_rule(domain, *body);
      if (!rule) return located(rule.error());
      into->add(std::move(*rule));
    }
  }
  return knowledge;
}

// The password the URL gives, if any (to keep it out of messages);
// nullopt if libpq cannot read the URL (its reason may quote the URL, so it
// is not passed on).
std::optional<std::string> password_in(const std::string& url) {
  char* error = nullptr;
  PQconninfoOption* options = PQconninfoParse(url.c_str(), &error);
  if (!options) {
    PQfreemem(error);
    return std::nullopt;
  }
  std::string password;
  for (PQconninfoOption* o = options; o->keyword; ++o)
    if (std::strcmp(o->keyword, "password") == 0 && o->val) password = o->val;
  PQconninfoFree(options);
  return password;
}

}  // namespace

Result<std::unique_ptr<StoreEngine>> open_postgres_store(const std::string& url, StoreAccess access,
                                                         const std::string& household, const std::string& robot) {
  const std::string where = scrub_store_location(url);
  auto secret = password_in(url);
  if (!secret)
    return make_error(ErrorCode::kInvalidInput,
                      where + ": not a PostgreSQL URL that can be read; the form is postgresql://USER@HOST:PORT/DATABASE");
  auto store = std::make_unique<PostgresStore>(url, where, *secret, access, household, robot);
  if (auto s = store->connect(); !s) return tl::unexpected(s.error());
  if (auto s = store->check_or_create_schema(); !s) return tl::unexpected(s.error());
  if (access == StoreAccess::kFresh)
    if (auto s = store->start_over(); !s) return tl::unexpected(s.error());
  return std::unique_ptr<StoreEngine>(std::move(store));
}

}  // namespace apprentice
