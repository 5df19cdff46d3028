#include "knowledge/store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>
#include <SQLiteCpp/SQLiteCpp.h>

#include "knowledge/store_creation.h"
#include "util/file.h"
#include "util/json.h"
#include "util/text.h"

namespace apprentice {

namespace {

using nlohmann::json;

constexpr int kBusyTimeoutMs = 5000;

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

// Strict readers of stored JSON: a value of another type is never
// converted (nlohmann would turn 1e300 into an int, and 0.5 into an
// index). They throw BadEntry, which load() reports as a damaged entry;
// nothing is thrown out of this file.
struct BadEntry : std::runtime_error {
  using std::runtime_error::runtime_error;
};
const json& member(const json& j, const char* key) {
  if (!j.is_object()) throw BadEntry(std::string("expected an object with '") + key + "'");
  auto it = j.find(key);
  if (it == j.end()) throw BadEntry(std::string("'") + key + "' is missing");
  return *it;
}
std::string text_at(const json& j, const char* key) {
  const json& v = member(j, key);
  if (!v.is_string() || v.get_ref<const std::string&>().empty()) throw BadEntry(std::string("'") + key + "' is not a name");
  return v.get<std::string>();
}
bool flag_at(const json& j, const char* key) {
  const json& v = member(j, key);
  if (!v.is_boolean()) throw BadEntry(std::string("'") + key + "' is not true or false");
  return v.get<bool>();
}
std::size_t index_below(const json& v, std::size_t count, const char* what) {
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() >= count) throw BadEntry(std::string("a stored ") + what + " names an undeclared variable");
  return static_cast<std::size_t>(v.get<std::uint64_t>());
}
const json& list_at(const json& j, const char* key) {
  const json& v = member(j, key);
  if (!v.is_array()) throw BadEntry(std::string("'") + key + "' is not a list");
  return v;
}

json literal_json(const Domain& domain, const Rule& rule, const LiteralPattern& l) {
  json args = json::array();
  for (std::uint8_t i = 0; i < l.atom.arity; ++i) args.push_back(l.atom.args[i]);
  (void)rule;
  return json{{"predicate", domain.predicates.at(l.atom.predicate).name}, {"positive", l.positive}, {"args", args}};
}

json rule_json(const Domain& domain, const Rule& rule) {
  json variables = json::array();
  for (const RuleVariable& v : rule.variables) {
    json j{{"name", v.name}, {"interest", v.object_of_interest}};
    if (v.category) j["category"] = *v.category;
    variables.push_back(j);
  }
  json goal = json::array(), conditions = json::array();
  for (const LiteralPattern& l : rule.goal) goal.push_back(literal_json(domain, rule, l));
  for (const LiteralPattern& l : rule.conditions) conditions.push_back(literal_json(domain, rule, l));
  json out{{"variables", variables}, {"goal", goal}, {"conditions", conditions},
           {"action", domain.actions.at(rule.action).name}, {"action_args", rule.action_args},
           {"steps", rule.steps_to_goal}};
  if (rule.subtask) out["subtask"] = *rule.subtask;
  return out;
}

Result<LiteralPattern> literal_from_json(const Domain& domain, const json& j, std::size_t variable_count) {
  LiteralPattern l;
  const std::string name = text_at(j, "predicate");
  auto predicate = domain.find_predicate(name);
  if (!predicate)
    return make_error(ErrorCode::kFailedPrecondition,
                      "a stored rule uses predicate " + name + ", which domain " + domain.name + " lacks");
  l.atom.predicate = *predicate;
  l.positive = flag_at(j, "positive");
  const json& args = list_at(j, "args");
  if (args.size() != domain.predicates[*predicate].parameter_types.size())
    return make_error(ErrorCode::kDataLoss, "a stored rule has the wrong arity for " + domain.predicates[*predicate].name);
  for (const json& a : args) l.atom.args[l.atom.arity++] = static_cast<VariableId>(index_below(a, variable_count, "rule"));
  return l;
}

Result<Rule> rule_from_json(const Domain& domain, const json& j) {
  Rule rule;
  const json& variables = list_at(j, "variables");
  if (variables.size() > kMaxRuleVariables) return make_error(ErrorCode::kDataLoss, "a stored rule has too many variables");
  for (const json& v : variables) {
    RuleVariable variable{text_at(v, "name"), std::nullopt, flag_at(v, "interest")};
    if (v.contains("category")) variable.category = text_at(v, "category");
    rule.variables.push_back(std::move(variable));
  }
  for (const char* part : {"goal", "conditions"}) {
    for (const json& l : list_at(j, part)) {
      auto literal = literal_from_json(domain, l, rule.variables.size());
      if (!literal) return tl::unexpected(literal.error());
      (std::string(part) == "goal" ? rule.goal : rule.conditions).push_back(*literal);
    }
  }
  const std::string action_name = text_at(j, "action");
  auto action = domain.find_action(action_name);
  if (!action)
    return make_error(ErrorCode::kFailedPrecondition,
                      "a stored rule uses action " + action_name + ", which domain " + domain.name + " lacks");
  rule.action = *action;
  for (const json& a : list_at(j, "action_args"))
    rule.action_args.push_back(static_cast<VariableId>(index_below(a, rule.variables.size(), "rule")));
  if (rule.action_args.size() != domain.actions[*action].parameters.size())
    return make_error(ErrorCode::kDataLoss, "a stored rule has the wrong arity for " + domain.actions[*action].name);
  const json& steps = member(j, "steps");
  if (!steps.is_number_unsigned() || steps.get<std::uint64_t>() > 1000) throw BadEntry("'steps' is not a small whole number");
  rule.steps_to_goal = static_cast<int>(steps.get<std::uint64_t>());
  if (j.contains("subtask")) rule.subtask = text_at(j, "subtask");
  // The matcher binds variables from the goal and the positive conditions
  // only; a rule whose action or negative conditions use any other
  // variable would act on no object at all.
  std::vector<bool> bound(rule.variables.size(), false);
  for (const auto* part : {&rule.goal, &rule.conditions})
    for (const LiteralPattern& l : *part)
      if (l.positive || part == &rule.goal)
        for (std::uint8_t i = 0; i < l.atom.arity; ++i) bound[l.atom.args[i]] = true;
  std::vector<VariableId> used(rule.action_args);
  for (const LiteralPattern& l : rule.conditions)
    if (!l.positive) used.insert(used.end(), l.atom.args.begin(), l.atom.args.begin() + l.atom.arity);
  for (VariableId v : used)
    if (!bound[v])
      return make_error(ErrorCode::kDataLoss, "a stored rule uses variable " + rule.variables[v].name +
                                                  ", which no goal literal or condition binds");
  return rule;
}

json goal_literals_json(const GoalKnowledge& g) {
  json out = json::array();
  for (const GoalTemplateLiteral& t : g.literals) {
    json args = json::array();
    for (const GoalTemplateArgument& a : t.arguments)
      args.push_back(a.object_of_interest ? json{{"interest", true}}
                     : a.properties.empty() ? json{{"category", a.category}}
                                            : json{{"category", a.category}, {"properties", a.properties}});
    out.push_back(json{{"predicate", t.predicate}, {"positive", t.positive}, {"args", args}});
  }
  return out;
}

// A stored goal's literals; each names a predicate of `domain` with its
// arity (kFailedPrecondition otherwise, as for rules).
Result<std::vector<GoalTemplateLiteral>> goal_literals_from_json(const Domain& domain, const json& j) {
  if (!j.is_array() || j.empty()) throw BadEntry("a stored goal is not a list of literals");
  std::vector<GoalTemplateLiteral> out;
  for (const json& t : j) {
    GoalTemplateLiteral literal{text_at(t, "predicate"), flag_at(t, "positive"), {}};
    auto predicate = domain.find_predicate(literal.predicate);
    if (!predicate)
      return make_error(ErrorCode::kFailedPrecondition,
                        "a stored goal uses predicate " + literal.predicate + ", which domain " + domain.name + " lacks");
    const json& args = list_at(t, "args");
    if (args.size() != domain.predicates[*predicate].parameter_types.size())
      return make_error(ErrorCode::kDataLoss, "a stored goal has the wrong arity for " + literal.predicate);
    for (const json& a : args) {
      if (a.contains("interest")) {
        if (!flag_at(a, "interest")) throw BadEntry("a goal argument is neither the object nor a category");
        literal.arguments.push_back(GoalTemplateArgument{true, "", {}});
      } else {
        std::vector<std::string> properties;
        if (a.contains("properties"))
          for (const json& p : list_at(a, "properties")) {
            if (!p.is_string()) throw BadEntry("a goal argument's property is not a word");
            properties.push_back(p.get<std::string>());
          }
        literal.arguments.push_back(GoalTemplateArgument{false, text_at(a, "category"), std::move(properties)});
      }
    }
    out.push_back(std::move(literal));
  }
  return out;
}

// A stored task structure: a non-empty list of {verb, relation, place}.
std::vector<LearnedSubtask> subtasks_from_json(const json& j) {
  if (!j.is_array() || j.empty()) throw BadEntry("a stored task structure is not a list of subtasks");
  std::vector<LearnedSubtask> out;
  for (const json& s : j) {
    LearnedSubtask subtask{text_at(s, "verb"), text_at(s, "relation"), text_at(s, "place")};
    if (subtask.relation != "on" && subtask.relation != "in")
      throw BadEntry("a stored subtask's relation is '" + subtask.relation + "', not on or in");
    out.push_back(std::move(subtask));
  }
  return out;
}

// The columns load() reads: a store without them is damaged.
constexpr const char* kTasksQuery = "SELECT name, structure FROM tasks ORDER BY name";
constexpr const char* kGoalsQuery = "SELECT task, subtask, category, place, literals, object, source FROM goals ORDER BY id";
constexpr const char* kRulesQuery = "SELECT body, object, source FROM rules ORDER BY id";

int table_count(SQLite::Database& db) {
  SQLite::Statement tables(db, "SELECT count(*) FROM sqlite_master WHERE type='table'");
  tables.executeStep();
  return tables.getColumn(0).getInt();
}

// Checks that the database is a store of this version with every table
// load() reads, creating the schema in an empty database when `may_create`.
// Creation happens in an immediate transaction that checks again, so two
// processes creating one store at once make one schema.
Status check_or_create_schema(SQLite::Database& db, const std::filesystem::path& path, bool may_create) {
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
  std::string format, version;
  SQLite::Statement meta(db, "SELECT key, value FROM meta");
  while (meta.executeStep()) {
    std::string key = meta.getColumn(0).getString();
    if (key == "format") format = meta.getColumn(1).getString();
    if (key == "schema_version") version = meta.getColumn(1).getString();
  }
  if (format != kKnowledgeFormatName)
    return make_error(ErrorCode::kFailedPrecondition, path.string() + " is not an apprentice knowledge store");
  if (version != std::to_string(kKnowledgeSchemaVersion))
    return make_error(ErrorCode::kFailedPrecondition,
                      path.string() + " was written with knowledge schema version " + version +
                          "; this apprentice reads version " + std::to_string(kKnowledgeSchemaVersion) +
                          ". Relearn into a new file, or use the apprentice version that wrote it.");
  for (auto [table, query] : {std::pair{"tasks", kTasksQuery}, {"goals", kGoalsQuery}, {"rules", kRulesQuery}}) {
    try {
      SQLite::Statement check(db, query);
    } catch (const SQLite::Exception& e) {
      if (e.getErrorCode() != SQLITE_ERROR) throw;
      return damaged(path, std::string("its ") + table + " table is missing or incomplete (" + e.what() + ")");
    }
  }
  return {};
}

// SQLite's quick_check: the pages and indexes are consistent.
Status quick_check(SQLite::Database& db, const std::filesystem::path& path) {
  SQLite::Statement check(db, "PRAGMA quick_check(1)");
  if (!check.executeStep()) return damaged(path, "PRAGMA quick_check gave no answer");
  std::string answer = check.getColumn(0).getString();
  if (answer != "ok") return damaged(path, "PRAGMA quick_check reports " + answer);
  return {};
}

}  // namespace

KnowledgeStore::KnowledgeStore(std::filesystem::path path, FileDescriptor lock, std::unique_ptr<SQLite::Database> db)
    : path_(std::move(path)), lock_(std::move(lock)), db_(std::move(db)) {}
KnowledgeStore::KnowledgeStore(KnowledgeStore&&) noexcept = default;
KnowledgeStore& KnowledgeStore::operator=(KnowledgeStore&& other) noexcept {
  // The database first, then its lock (as in the destructor).
  db_ = std::move(other.db_);
  lock_ = std::move(other.lock_);
  path_ = std::move(other.path_);
  return *this;
}
KnowledgeStore::~KnowledgeStore() { db_.reset(); }

Result<KnowledgeStore> KnowledgeStore::open(const std::filesystem::path& path, StoreAccess access) {
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
    if (auto status = check_or_create_schema(*db, path, !read_only); !status) return tl::unexpected(status.error());
    if (access == StoreAccess::kFresh) {
      SQLite::Transaction transaction(*db, SQLite::TransactionBehavior::IMMEDIATE);
      db->exec("DELETE FROM goals");
      db->exec("DELETE FROM tasks");
      db->exec("DELETE FROM rules");
      transaction.commit();
    }
    return KnowledgeStore(path, std::move(lock), std::move(db));
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path, e));
  }
}

Status KnowledgeStore::save_goal(const GoalKnowledge& goal) {
  try {
    SQLite::Transaction transaction(*db_);
    SQLite::Statement insert(*db_,
                             "INSERT OR REPLACE INTO goals(task, subtask, category, place, literals, object, source) "
                             "VALUES (?, ?, ?, ?, ?, ?, ?)");
    insert.bind(1, goal.key.task);
    insert.bind(2, goal.key.subtask);
    insert.bind(3, goal.key.category);
    insert.bind(4, goal.key.place);
    insert.bind(5, dump_json(goal_literals_json(goal)));
    insert.bind(6, goal.provenance.object);
    insert.bind(7, goal.provenance.source);
    insert.exec();
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
}

Status KnowledgeStore::save_rule(const Domain& domain, const Rule& rule) {
  try {
    SQLite::Transaction transaction(*db_);
    SQLite::Statement insert(*db_, "INSERT OR IGNORE INTO rules(signature, body, object, source) VALUES (?, ?, ?, ?)");
    insert.bind(1, rule_signature(domain, rule));
    insert.bind(2, dump_json(rule_json(domain, rule)));
    insert.bind(3, rule.provenance.object);
    insert.bind(4, rule.provenance.source);
    insert.exec();
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
}

const TaskKnowledge* Knowledge::find_task(const std::string& name) const {
  for (const TaskKnowledge& t : tasks)
    if (t.name == name) return &t;
  return nullptr;
}

Status KnowledgeStore::save_task(const TaskKnowledge& task) {
  try {
    json subtasks = json::array();
    for (const LearnedSubtask& s : task.subtasks)
      subtasks.push_back(json{{"verb", s.verb}, {"relation", s.relation}, {"place", s.place_category}});
    SQLite::Transaction transaction(*db_);
    SQLite::Statement insert(*db_, "INSERT OR REPLACE INTO tasks(name, structure) VALUES (?, ?)");
    insert.bind(1, task.name);
    insert.bind(2, dump_json(subtasks));
    insert.exec();
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
}

namespace {

// Runs one DELETE with text parameters in its own transaction.
Status delete_rows(SQLite::Database& db, const std::filesystem::path& path, const char* sql,
                   const std::vector<std::string>& parameters) {
  try {
    SQLite::Transaction transaction(db);
    SQLite::Statement remove(db, sql);
    for (std::size_t i = 0; i < parameters.size(); ++i) remove.bind(static_cast<int>(i + 1), parameters[i]);
    remove.exec();
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path, e));
  }
}

}  // namespace

Status KnowledgeStore::remove_goal(const GoalKey& key) {
  return delete_rows(*db_, path_, "DELETE FROM goals WHERE task = ? AND subtask = ? AND category = ? AND place = ?",
                     {key.task, key.subtask, key.category, key.place});
}

Status KnowledgeStore::remove_rule(const Domain& domain, const Rule& rule) {
  return delete_rows(*db_, path_, "DELETE FROM rules WHERE signature = ?", {rule_signature(domain, rule)});
}

Status KnowledgeStore::remove_task(const std::string& name) {
  return delete_rows(*db_, path_, "DELETE FROM tasks WHERE name = ?", {name});
}

Result<Knowledge> KnowledgeStore::load(const Domain& domain) const {
  Knowledge knowledge;
  // Which entry is being read, for the message if it is damaged.
  std::string entry;
  auto parse = [&](const SQLite::Column& column) {
    if (!column.isText()) throw BadEntry("not text");
    return json::parse(column.getString());
  };
  try {
    // One read transaction: a consistent snapshot while writers go on.
    SQLite::Transaction snapshot(*db_, SQLite::TransactionBehavior::DEFERRED);
    SQLite::Statement tasks(*db_, kTasksQuery);
    while (tasks.executeStep()) {
      entry = "the task " + apprentice::quoted(tasks.getColumn(0).getString());
      knowledge.tasks.push_back(TaskKnowledge{tasks.getColumn(0).getString(), subtasks_from_json(parse(tasks.getColumn(1)))});
    }
    SQLite::Statement goals(*db_, kGoalsQuery);
    while (goals.executeStep()) {
      GoalKnowledge g;
      g.key = GoalKey{goals.getColumn(0).getString(), goals.getColumn(1).getString(),
                      goals.getColumn(2).getString(), goals.getColumn(3).getString()};
      entry = "the goal for " + g.key.category + " (" + g.key.subtask + ")";
      auto literals = goal_literals_from_json(domain, parse(goals.getColumn(4)));
      if (!literals) return tl::unexpected(prefix_error(literals.error(), path_.string()));
      g.literals = std::move(*literals);
      g.provenance = Provenance{goals.getColumn(5).getString(), goals.getColumn(6).getString()};
      knowledge.goals.add(std::move(g));
    }
    SQLite::Statement rules(*db_, kRulesQuery);
    while (rules.executeStep()) {
      entry = "a rule";
      auto rule = rule_from_json(domain, parse(rules.getColumn(0)));
      if (!rule) return tl::unexpected(prefix_error(rule.error(), path_.string()));
      rule->provenance = Provenance{rules.getColumn(1).getString(), rules.getColumn(2).getString()};
      knowledge.rules.add(domain, std::move(*rule));
    }
  } catch (const BadEntry& e) {
    return make_error(ErrorCode::kDataLoss, path_.string() + ": a stored entry is unreadable: " + entry + ": " + e.what());
  } catch (const json::exception& e) {
    return make_error(ErrorCode::kDataLoss, path_.string() + ": a stored entry is unreadable: " + entry + ": " + e.what());
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
  return knowledge;
}

Result<Knowledge> load_knowledge_read_only(const std::filesystem::path& path, const Domain& domain) {
  auto store = KnowledgeStore::open(path, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  return store->load(domain);
}

}  // namespace apprentice
