#include "knowledge/store.h"

#include <fstream>
#include <string_view>

#include <nlohmann/json.hpp>
#include <SQLiteCpp/SQLiteCpp.h>

namespace apprentice {

namespace {

using nlohmann::json;

constexpr const char* kFormatName = "apprentice-knowledge";

constexpr const char* kUnreadable = " (the file is not a readable apprentice knowledge store)";

Error sqlite_error(const std::filesystem::path& path, const std::exception& e) {
  std::string message = path.string() + ": " + e.what();
  if (message.find("not a database") != std::string::npos || message.find("malformed") != std::string::npos)
    return Error{ErrorCode::kDataLoss, message + kUnreadable};
  return Error{ErrorCode::kIo, message};
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
  auto predicate = domain.find_predicate(j.at("predicate").get<std::string>());
  if (!predicate)
    return make_error(ErrorCode::kFailedPrecondition,
                      "a stored rule uses predicate " + j.at("predicate").get<std::string>() +
                          ", which domain " + domain.name + " lacks");
  l.atom.predicate = *predicate;
  l.positive = j.at("positive").get<bool>();
  const json& args = j.at("args");
  if (args.size() != domain.predicates[*predicate].parameter_types.size())
    return make_error(ErrorCode::kDataLoss, "a stored rule has the wrong arity for " + domain.predicates[*predicate].name);
  for (const json& a : args) {
    auto v = a.get<std::size_t>();
    if (v >= variable_count) return make_error(ErrorCode::kDataLoss, "a stored rule names an undeclared variable");
    l.atom.args[l.atom.arity++] = static_cast<VariableId>(v);
  }
  return l;
}

Result<Rule> rule_from_json(const Domain& domain, const json& j) {
  Rule rule;
  for (const json& v : j.at("variables")) {
    RuleVariable variable{v.at("name").get<std::string>(), std::nullopt, v.at("interest").get<bool>()};
    if (v.contains("category")) variable.category = v.at("category").get<std::string>();
    rule.variables.push_back(std::move(variable));
  }
  if (rule.variables.size() > kMaxRuleVariables) return make_error(ErrorCode::kDataLoss, "a stored rule has too many variables");
  for (const char* part : {"goal", "conditions"}) {
    for (const json& l : j.at(part)) {
      auto literal = literal_from_json(domain, l, rule.variables.size());
      if (!literal) return tl::unexpected(literal.error());
      (std::string(part) == "goal" ? rule.goal : rule.conditions).push_back(*literal);
    }
  }
  auto action = domain.find_action(j.at("action").get<std::string>());
  if (!action)
    return make_error(ErrorCode::kFailedPrecondition, "a stored rule uses action " + j.at("action").get<std::string>() +
                                                          ", which domain " + domain.name + " lacks");
  rule.action = *action;
  for (const json& a : j.at("action_args")) {
    auto v = a.get<std::size_t>();
    if (v >= rule.variables.size()) return make_error(ErrorCode::kDataLoss, "a stored rule names an undeclared variable");
    rule.action_args.push_back(static_cast<VariableId>(v));
  }
  if (rule.action_args.size() != domain.actions[*action].parameters.size())
    return make_error(ErrorCode::kDataLoss, "a stored rule has the wrong arity for " + domain.actions[*action].name);
  rule.steps_to_goal = j.at("steps").get<int>();
  if (j.contains("subtask")) rule.subtask = j.at("subtask").get<std::string>();
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

std::vector<GoalTemplateLiteral> goal_literals_from_json(const json& j) {
  std::vector<GoalTemplateLiteral> out;
  for (const json& t : j) {
    GoalTemplateLiteral literal{t.at("predicate").get<std::string>(), t.at("positive").get<bool>(), {}};
    for (const json& a : t.at("args")) {
      if (a.contains("interest")) literal.arguments.push_back(GoalTemplateArgument{true, "", {}});
      else
        literal.arguments.push_back(GoalTemplateArgument{
            false, a.at("category").get<std::string>(),
            a.contains("properties") ? a.at("properties").get<std::vector<std::string>>() : std::vector<std::string>{}});
    }
    out.push_back(std::move(literal));
  }
  return out;
}

Status check_or_create_schema(SQLite::Database& db, const std::filesystem::path& path) {
  bool has_meta = db.tableExists("meta");
  if (!has_meta) {
    SQLite::Statement tables(db, "SELECT count(*) FROM sqlite_master WHERE type='table'");
    tables.executeStep();
    if (tables.getColumn(0).getInt() > 0)
      return make_error(ErrorCode::kFailedPrecondition,
                        path.string() + " is an SQLite database of another program, not an apprentice knowledge store");
    SQLite::Transaction transaction(db);
    db.exec("CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    db.exec("CREATE TABLE goals(id INTEGER PRIMARY KEY, task TEXT NOT NULL, subtask TEXT NOT NULL, "
            "category TEXT NOT NULL, place TEXT NOT NULL, literals TEXT NOT NULL, object TEXT NOT NULL, "
            "source TEXT NOT NULL, UNIQUE(task, subtask, category, place))");
    db.exec("CREATE TABLE tasks(name TEXT PRIMARY KEY, structure TEXT NOT NULL)");
    db.exec("CREATE TABLE rules(id INTEGER PRIMARY KEY, signature TEXT NOT NULL UNIQUE, body TEXT NOT NULL, "
            "object TEXT NOT NULL, source TEXT NOT NULL)");
    SQLite::Statement insert(db, "INSERT INTO meta(key, value) VALUES (?, ?)");
    for (auto [key, value] : {std::pair<std::string, std::string>{"format", kFormatName},
                              {"schema_version", std::to_string(kKnowledgeSchemaVersion)}}) {
      insert.bind(1, key);
      insert.bind(2, value);
      insert.exec();
      insert.reset();
    }
    transaction.commit();
    return {};
  }
  std::string format, version;
  SQLite::Statement meta(db, "SELECT key, value FROM meta");
  while (meta.executeStep()) {
    std::string key = meta.getColumn(0).getString();
    if (key == "format") format = meta.getColumn(1).getString();
    if (key == "schema_version") version = meta.getColumn(1).getString();
  }
  if (format != kFormatName)
    return make_error(ErrorCode::kFailedPrecondition, path.string() + " is not an apprentice knowledge store");
  if (version != std::to_string(kKnowledgeSchemaVersion))
    return make_error(ErrorCode::kFailedPrecondition,
                      path.string() + " was written with knowledge schema version " + version +
                          "; this apprentice reads version " + std::to_string(kKnowledgeSchemaVersion) +
                          ". Relearn into a new file, or use the apprentice version that wrote it.");
  return {};
}

// A file that exists with content must be an SQLite database. SQLite
// itself takes a 1-byte file for an empty database (a workaround for an old
// kernel bug) and would overwrite it with a new store.
Status check_sqlite_header(const std::filesystem::path& path) {
  std::error_code ec;
  auto size = std::filesystem::file_size(path, ec);
  if (ec || size == 0) return {};  // absent (created below) or empty: a new store
  constexpr std::string_view kHeader("SQLite format 3\0", 16);
  std::string head(kHeader.size(), '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (in.gcount() == static_cast<std::streamsize>(head.size()) && head == kHeader) return {};
  return make_error(ErrorCode::kDataLoss, path.string() + ": file is not a database" + kUnreadable);
}

}  // namespace

KnowledgeStore::KnowledgeStore(std::filesystem::path path, std::unique_ptr<SQLite::Database> db)
    : path_(std::move(path)), db_(std::move(db)) {}
KnowledgeStore::KnowledgeStore(KnowledgeStore&&) noexcept = default;
KnowledgeStore& KnowledgeStore::operator=(KnowledgeStore&&) noexcept = default;
KnowledgeStore::~KnowledgeStore() = default;

Result<KnowledgeStore> KnowledgeStore::open(const std::filesystem::path& path) {
  if (auto status = check_sqlite_header(path); !status) return tl::unexpected(status.error());
  try {
    auto db = std::make_unique<SQLite::Database>(path.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
    db->exec("PRAGMA busy_timeout = 5000");
    // A rollback journal with full syncs: a transaction that returned is on
    // disk, and a killed writer leaves a journal SQLite rolls back.
    db->exec("PRAGMA journal_mode = DELETE");
    db->exec("PRAGMA synchronous = FULL");
    auto status = check_or_create_schema(*db, path);
    if (!status) return tl::unexpected(status.error());
    return KnowledgeStore(path, std::move(db));
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
    insert.bind(5, goal_literals_json(goal).dump());
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
    insert.bind(2, rule_json(domain, rule).dump());
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
    insert.bind(2, subtasks.dump());
    insert.exec();
    transaction.commit();
    return {};
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
}

Result<Knowledge> KnowledgeStore::load(const Domain& domain) const {
  Knowledge knowledge;
  try {
    SQLite::Statement tasks(*db_, "SELECT name, structure FROM tasks ORDER BY name");
    while (tasks.executeStep()) {
      TaskKnowledge task{tasks.getColumn(0).getString(), {}};
      for (const json& s : json::parse(tasks.getColumn(1).getString()))
        task.subtasks.push_back(LearnedSubtask{s.at("verb").get<std::string>(), s.at("relation").get<std::string>(),
                                               s.at("place").get<std::string>()});
      knowledge.tasks.push_back(std::move(task));
    }
    SQLite::Statement goals(*db_, "SELECT task, subtask, category, place, literals, object, source FROM goals ORDER BY id");
    while (goals.executeStep()) {
      GoalKnowledge g;
      g.key = GoalKey{goals.getColumn(0).getString(), goals.getColumn(1).getString(),
                      goals.getColumn(2).getString(), goals.getColumn(3).getString()};
      g.literals = goal_literals_from_json(json::parse(goals.getColumn(4).getString()));
      g.provenance = Provenance{goals.getColumn(5).getString(), goals.getColumn(6).getString()};
      knowledge.goals.add(std::move(g));
    }
    SQLite::Statement rules(*db_, "SELECT body, object, source FROM rules ORDER BY id");
    while (rules.executeStep()) {
      auto rule = rule_from_json(domain, json::parse(rules.getColumn(0).getString()));
      if (!rule) return tl::unexpected(prefix_error(rule.error(), path_.string()));
      rule->provenance = Provenance{rules.getColumn(1).getString(), rules.getColumn(2).getString()};
      knowledge.rules.add(domain, std::move(*rule));
    }
  } catch (const json::exception& e) {
    return make_error(ErrorCode::kDataLoss, path_.string() + ": a stored entry is unreadable: " + e.what());
  } catch (const std::exception& e) {
    return tl::unexpected(sqlite_error(path_, e));
  }
  return knowledge;
}

}  // namespace apprentice
