#include "knowledge/store_sql.h"

#include "knowledge/preferences.h"
#include "knowledge/rule.h"

namespace apprentice::store_sql {

std::string numbered_placeholders(std::string_view sql) {
  std::string out;
  out.reserve(sql.size() + 16);
  int n = 0;
  for (char c : sql) {
    if (c == '?')
      out += "$" + std::to_string(++n);
    else
      out += c;
  }
  return out;
}

std::vector<std::string> schema(std::string_view id) {
  const std::string i(id);
  return {
      "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)",
      "CREATE TABLE goals(id " + i +
          ", household TEXT NOT NULL, task TEXT NOT NULL, subtask TEXT NOT NULL, category TEXT NOT NULL, "
          "place TEXT NOT NULL, literals TEXT NOT NULL, object TEXT NOT NULL, source TEXT NOT NULL, "
          "robot TEXT NOT NULL DEFAULT '', UNIQUE(household, task, subtask, category, place))",
      "CREATE TABLE tasks(household TEXT NOT NULL, name TEXT NOT NULL, structure TEXT NOT NULL, "
      "PRIMARY KEY(household, name))",
      "CREATE TABLE rules(id " + i +
          ", signature TEXT NOT NULL UNIQUE, body TEXT NOT NULL, object TEXT NOT NULL, source TEXT NOT NULL, "
          "robot TEXT NOT NULL DEFAULT '')",
      class_rules_tables(id)[0],
      class_rules_tables(id)[1],
  };
}

std::vector<std::string> class_rules_tables(std::string_view id) {
  const std::string i(id);
  return {"CREATE TABLE class_rules(id " + i +
              ", household TEXT NOT NULL, key TEXT NOT NULL, body TEXT NOT NULL, source TEXT NOT NULL, "
              "UNIQUE(household, key))",
          "CREATE TABLE forgotten_rules(id " + i +
              ", household TEXT NOT NULL, key TEXT NOT NULL, body TEXT NOT NULL, UNIQUE(household, key))"};
}

int version_number(const std::string& text) {
  for (int v = kOldestMigratedSchemaVersion; v <= kKnowledgeSchemaVersion; ++v)
    if (text == std::to_string(v)) return v;
  return 0;
}

std::string other_version(const std::string& where, const std::string& version) {
  return where + " was written with knowledge schema version " + version + "; this apprentice reads version " +
         std::to_string(kKnowledgeSchemaVersion) +
         ". Relearn into a new store, or use the apprentice version that wrote it.";
}

const char* households_query(int version) {
  return version == 1 ? kHouseholdsV1 : version == 2 ? kHouseholdsV2 : kHouseholds;
}

std::string robot_column(int version) { return version >= 4 ? "robot" : "''"; }

std::string goal_by_key(int version) {
  return "SELECT literals, object, source, " + robot_column(version) +
         " FROM goals WHERE household = ? AND task = ? AND subtask = ? AND category = ? AND place = ?";
}

std::string rule_by_signature(int version) {
  return "SELECT body, object, source, " + robot_column(version) + " FROM rules WHERE signature = ?";
}

std::string new_goals(int version) {
  return "SELECT id, task, subtask, category, place, literals, object, source, " + robot_column(version) +
         " FROM goals WHERE household = ? AND id > ? ORDER BY id";
}

std::string new_rules(int version) {
  return "SELECT id, body, object, source, " + robot_column(version) + " FROM rules WHERE id > ? ORDER BY id";
}

Status SqlEngine::remove_goal(const GoalKey& key) {
  return execute(kRemoveGoal, {household_, key.task, key.subtask, key.category, key.place});
}

Status SqlEngine::remove_rule(const Domain& domain, const Rule& rule) {
  return execute(kRemoveRule, {rule_signature(domain, rule)});
}

Status SqlEngine::remove_task(const std::string& name) { return execute(kRemoveTask, {household_, name}); }

Status SqlEngine::remove_class_rule(const ClassRule& rule) {
  return execute(kRemoveClassRule, {household_, class_rule_key(rule)});
}

}  // namespace apprentice::store_sql
