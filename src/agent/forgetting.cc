#include "agent/forgetting.h"

#include <algorithm>

#include "agent/class_rule_knowledge.h"
#include "agent/goal_proposals.h"
#include "agent/teacher_questions.h"
#include "language/narration_conversation.h"

namespace apprentice {

namespace {

// The rules `what` names, or why none is forgotten.
ForgetDecision decide_rules(const std::string& what, const std::optional<std::string>& category,
                            std::span<const ClassRule> rules_in_use) {
  ForgetDecision d;
  std::vector<ClassRule> named = rules_named(rules_in_use, what);
  if (named.empty()) {
    d.reply = language::nothing_to_forget(category ? std::optional<std::string_view>(*category) : std::nullopt, what);
    return d;
  }
  std::vector<std::string> said;
  for (const ClassRule& rule : named)
    if (std::find(said.begin(), said.end(), say_class_rule(rule)) == said.end()) said.push_back(say_class_rule(rule));
  if (said.size() > 1) {
    d.kind = ForgetDecision::Kind::kWhichRule;
    const ClassRule& first = named.front();
    d.reply = language::which_rule_to_forget(what, said, rule_subject(first) + " " + rule_destination(first));
    return d;
  }
  d.kind = ForgetDecision::Kind::kRules;
  d.rules = std::move(named);
  d.reply = language::forgot_rule(said.front());
  return d;
}

}  // namespace

ForgetDecision decide_forget(const std::string& what, std::optional<std::string> category, const GoalMemory& goals,
                             std::span<const ClassRule> rules_in_use) {
  if (category && kinds_known_by(goals, what) != std::vector<std::string>{*category} &&
      !rules_named(rules_in_use, what).empty())
    category.reset();
  if (!category) {
    // A kind that is not here may still be known.
    std::vector<std::string> fits = kinds_known_by(goals, what);
    if (fits.size() > 1) {
      ForgetDecision d;
      d.kind = ForgetDecision::Kind::kWhichKind;
      d.reply = language::which_kind_to_forget(fits);
      return d;
    }
    if (fits.size() == 1) category = fits.front();
  }
  std::vector<GoalKey> keys;
  if (category)
    for (const GoalKnowledge& g : goals.all())
      if (g.key.category == *category) keys.push_back(g.key);
  if (keys.empty()) return decide_rules(what, category, rules_in_use);
  ForgetDecision d;
  d.kind = ForgetDecision::Kind::kGoals;
  d.category = *category;
  d.goals = std::move(keys);
  d.reply = language::forgot_where_kind_goes(*category);
  return d;
}

}  // namespace apprentice
