#include "knowledge/store_codec.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/json.h"
#include "util/text.h"

namespace apprentice::store_codec {

namespace {

using nlohmann::json;

// Strict readers of stored JSON: a value of another type is never
// converted (nlohmann would turn 1e300 into an int, and 0.5 into an
// index). They throw BadEntry, which decode_* reports as an unreadable entry;
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

json words_json(const std::vector<std::string>& words) {
  json out = json::array();
  for (const std::string& w : words) out.push_back(w);
  return out;
}

std::vector<std::string> words_at(const json& j, const char* key) {
  std::vector<std::string> out;
  for (const json& w : list_at(j, key)) {
    if (!w.is_string() || w.get_ref<const std::string&>().empty()) throw BadEntry(std::string("'") + key + "' holds something that is not a word");
    out.push_back(w.get<std::string>());
  }
  return out;
}

// A string that may be empty (a rule's class, its sentence, its scope).
std::string maybe_text_at(const json& j, const char* key) {
  const json& v = member(j, key);
  if (!v.is_string()) throw BadEntry(std::string("'") + key + "' is not text");
  return v.get<std::string>();
}

json class_rule_json(const ClassRule& rule) {
  GoalKnowledge destination;
  destination.literals = destination_literals(rule.destination);
  return json{{"class", rule.class_name},
              {"class_id", rule.class_id},
              {"modifiers", words_json(rule.modifiers)},
              {"rest", rule.rest},
              {"destination", goal_literals_json(destination)},
              {"exceptions", words_json(rule.exceptions)},
              {"source", std::string(rule_source_name(rule.source))},
              {"said", rule.said},
              {"evidence", words_json(rule.evidence)},
              {"confidence", rule.confidence},
              {"scope", json{{"task", rule.scope.task}, {"subtask", rule.scope.subtask}, {"place", rule.scope.place}}}};
}

Result<ClassRule> class_rule_from_json(const Domain& domain, const json& j) {
  ClassRule rule;
  rule.class_name = maybe_text_at(j, "class");
  rule.class_id = maybe_text_at(j, "class_id");
  rule.modifiers = words_at(j, "modifiers");
  rule.rest = flag_at(j, "rest");
  auto literals = goal_literals_from_json(domain, member(j, "destination"));
  if (!literals) return tl::unexpected(literals.error());
  auto destination = destination_of(*literals);
  if (!destination) throw BadEntry("its destination is not a place to put a thing");
  rule.destination = std::move(*destination);
  rule.exceptions = words_at(j, "exceptions");
  auto source = rule_source_from_name(text_at(j, "source"));
  if (!source) throw BadEntry("'source' is not induced, person, llm or fleet");
  rule.source = *source;
  rule.said = maybe_text_at(j, "said");
  rule.evidence = words_at(j, "evidence");
  const json& confidence = member(j, "confidence");
  if (!confidence.is_number() || !(confidence.get<double>() >= 0 && confidence.get<double>() <= 1))
    throw BadEntry("'confidence' is not a number from 0 to 1");
  rule.confidence = confidence.get<double>();
  const json& scope = member(j, "scope");
  rule.scope = GoalScope{maybe_text_at(scope, "task"), maybe_text_at(scope, "subtask"), maybe_text_at(scope, "place")};
  return rule;
}

}  // namespace

std::string encode_class_rule(const ClassRule& rule) { return dump_json(class_rule_json(rule)); }

std::string encode_goal_literals(const GoalKnowledge& goal) { return dump_json(goal_literals_json(goal)); }

std::string encode_rule(const Domain& domain, const Rule& rule) { return dump_json(rule_json(domain, rule)); }

std::string encode_subtasks(const TaskKnowledge& task) {
  json subtasks = json::array();
  for (const LearnedSubtask& s : task.subtasks)
    subtasks.push_back(json{{"verb", s.verb}, {"relation", s.relation}, {"place", s.place_category}});
  return dump_json(subtasks);
}

std::string goal_entry(const GoalKey& key) { return "the goal for " + key.category + " (" + key.subtask + ")"; }

std::string task_entry(const std::string& name) { return "the task " + apprentice::quoted(name); }

Error unreadable(const std::string& entry, const std::string& why) {
  return Error{ErrorCode::kDataLoss, "a stored entry is unreadable: " + entry + ": " + why};
}

namespace {

// Runs a reader, turning what it throws into the entry's error.
template <typename T, typename Read>
Result<T> reading(const std::string& entry, Read read) {
  try {
    return read();
  } catch (const BadEntry& e) {
    return tl::unexpected(unreadable(entry, e.what()));
  } catch (const std::exception& e) {
    return tl::unexpected(unreadable(entry, e.what()));
  }
}

}  // namespace

Result<GoalKnowledge> decode_goal(const Domain& domain, GoalKey key, std::string_view literals, Provenance provenance) {
  const std::string entry = goal_entry(key);
  return reading<GoalKnowledge>(entry, [&]() -> Result<GoalKnowledge> {
    auto read = goal_literals_from_json(domain, json::parse(literals));
    if (!read) return tl::unexpected(read.error());
    GoalKnowledge goal;
    goal.key = std::move(key);
    goal.literals = std::move(*read);
    goal.provenance = std::move(provenance);
    return goal;
  });
}

Result<Rule> decode_rule(const Domain& domain, std::string_view body, Provenance provenance) {
  return reading<Rule>(kRuleEntry, [&]() -> Result<Rule> {
    auto rule = rule_from_json(domain, json::parse(body));
    if (!rule) return tl::unexpected(rule.error());
    rule->provenance = std::move(provenance);
    return rule;
  });
}

Result<ClassRule> decode_class_rule(const Domain& domain, std::string_view body) {
  return reading<ClassRule>(kClassRuleEntry, [&]() -> Result<ClassRule> { return class_rule_from_json(domain, json::parse(body)); });
}

Result<TaskKnowledge> decode_task(const std::string& name, std::string_view structure) {
  return reading<TaskKnowledge>(task_entry(name), [&]() -> Result<TaskKnowledge> {
    return TaskKnowledge{name, subtasks_from_json(json::parse(structure))};
  });
}

}  // namespace apprentice::store_codec
