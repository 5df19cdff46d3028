#include "knowledge/preferences.h"

#include <algorithm>
#include <cstdio>

#include "util/text.h"

namespace apprentice {

namespace {

bool is_placing(const GoalTemplateLiteral& literal) {
  return literal.positive && (literal.predicate == "in" || literal.predicate == "on") && literal.arguments.size() == 2 &&
         literal.arguments[0].object_of_interest && !literal.arguments[1].object_of_interest;
}

std::string place_text(const GoalTemplateArgument& place) {
  std::string text = place.category;
  for (auto p = place.properties.rbegin(); p != place.properties.rend(); ++p) text = *p + " " + text;
  return place.properties.empty() ? text : "[" + text + "]";
}

}  // namespace

std::optional<Destination> destination_of(std::span<const GoalTemplateLiteral> literals) {
  const GoalTemplateLiteral* placing = nullptr;
  for (const GoalTemplateLiteral& literal : literals) {
    if (!is_placing(literal)) continue;
    if (placing != nullptr) return std::nullopt;  // two places
    placing = &literal;
  }
  if (placing == nullptr) return std::nullopt;
  Destination destination{placing->predicate, placing->arguments[1], {}};
  for (const GoalTemplateLiteral& literal : literals) {
    if (&literal == placing) continue;
    bool about_place = !literal.arguments.empty() &&
                       std::all_of(literal.arguments.begin(), literal.arguments.end(),
                                   [&](const GoalTemplateArgument& a) { return a == destination.place; });
    if (!about_place) return std::nullopt;
    destination.doors.push_back(literal);
  }
  return destination;
}

std::vector<GoalTemplateLiteral> destination_literals(const Destination& destination) {
  std::vector<GoalTemplateLiteral> out;
  out.push_back(GoalTemplateLiteral{destination.relation, true, {GoalTemplateArgument{true, "", {}}, destination.place}});
  out.insert(out.end(), destination.doors.begin(), destination.doors.end());
  return out;
}

std::string format_destination(const Destination& destination) {
  std::string out = destination.relation + " the " + place_text(destination.place);
  if (destination.doors.empty()) return out;
  std::vector<std::string> doors;
  for (const GoalTemplateLiteral& door : destination.doors) {
    std::string atom = "(" + door.predicate;
    for (const GoalTemplateArgument& a : door.arguments) atom += " " + place_text(a);
    atom += ")";
    doors.push_back(door.positive ? atom : "(not " + atom + ")");
  }
  return out + " " + join(doors, " ");
}

std::string_view rule_source_name(RuleSource source) {
  switch (source) {
    case RuleSource::kInduced: return "induced";
    case RuleSource::kPerson: return "person";
    case RuleSource::kLlm: return "llm";
    case RuleSource::kFleet: return "fleet";
  }
  return "induced";
}

std::optional<RuleSource> rule_source_from_name(std::string_view name) {
  for (RuleSource source : {RuleSource::kInduced, RuleSource::kPerson, RuleSource::kLlm, RuleSource::kFleet})
    if (rule_source_name(source) == name) return source;
  return std::nullopt;
}

std::string class_rule_key(const ClassRule& rule) {
  std::string out = std::string(rule_source_name(rule.source)) + "|" + rule.scope.task + "|" + rule.scope.subtask + "|" +
                    rule.scope.place + "|" + (rule.class_id.empty() ? rule.class_name : rule.class_id) + "|" +
                    join(rule.modifiers, " ") + "|" + (rule.rest ? "rest" : "") + "|" +
                    format_destination(rule.destination);
  return out;
}

std::string format_class_rule(const ClassRule& rule) {
  std::string what = rule.class_name.empty() ? (rule.rest ? "the rest" : "anything") : rule.class_name;
  if (rule.rest && !rule.class_name.empty()) what = "other " + what;
  if (!rule.modifiers.empty()) what = join(rule.modifiers, " ") + " " + what;
  char confidence[16];
  std::snprintf(confidence, sizeof confidence, "%.2f", rule.confidence);
  std::string out = what + " -> " + format_destination(rule.destination) + " (" +
                    std::string(rule_source_name(rule.source));
  if (!rule.evidence.empty()) out += " from " + join(rule.evidence, ", ");
  if (!rule.exceptions.empty()) out += "; except " + join(rule.exceptions, ", ");
  return out + "; " + confidence + ")";
}

void ClassRules::add(ClassRule rule) {
  if (ClassRule* known = find(rule)) {
    *known = std::move(rule);
    return;
  }
  rules_.push_back(std::move(rule));
}

bool ClassRules::remove(const ClassRule& rule) {
  const std::string key = class_rule_key(rule);
  auto it = std::find_if(rules_.begin(), rules_.end(), [&](const ClassRule& r) { return class_rule_key(r) == key; });
  if (it == rules_.end()) return false;
  rules_.erase(it);
  return true;
}

const ClassRule* ClassRules::find(const ClassRule& rule) const {
  const std::string key = class_rule_key(rule);
  for (const ClassRule& r : rules_)
    if (class_rule_key(r) == key) return &r;
  return nullptr;
}

ClassRule* ClassRules::find(const ClassRule& rule) {
  return const_cast<ClassRule*>(static_cast<const ClassRules*>(this)->find(rule));
}

}  // namespace apprentice
