#include "agent/person_rule.h"

#include "util/text.h"

namespace apprentice {

Destination destination_at(const World& world, ObjectId place) {
  const ObjectInfo& info = world.universe->info(place);
  Destination destination;
  destination.relation = info.kind == ObjectKind::kSurface ? "on" : "in";
  destination.place = GoalTemplateArgument{false, info.category, {}};
  if (world.universe->with_category(info.category).size() != 1) destination.place.properties = info.properties;
  return destination;
}

std::vector<ClassRule> class_rules_of(const World& world, const language::RuleReading& reading, RuleSource source,
                                      const std::string& said, const GoalScope& scope, double confidence) {
  std::vector<ClassRule> rules;
  for (const language::RuleClause& clause : reading.clauses) {
    if (clause.thing || clause.places.empty()) continue;
    for (const language::RuleClass& said_class : clause.classes) {
      for (ObjectId place : clause.places) {
        ClassRule rule;
        if (said_class.phrase.empty() || language::is_general_head(said_class.head)) {
          rule.modifiers = said_class.modifiers;
        } else {
          rule.class_name = said_class.phrase;
        }
        rule.rest = said_class.rest;
        rule.destination = destination_at(world, place);
        rule.source = source;
        rule.said = said;
        rule.confidence = confidence / static_cast<double>(clause.places.size());
        rule.scope = scope;
        rules.push_back(std::move(rule));
      }
    }
  }
  return rules;
}

}  // namespace apprentice
