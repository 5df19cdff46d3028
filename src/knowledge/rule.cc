#include "knowledge/rule.h"

namespace apprentice {

namespace {

std::string format_pattern(const Domain& domain, const Rule& rule, const LiteralPattern& l) {
  std::string atom = "(" + domain.predicates.at(l.atom.predicate).name;
  for (std::uint8_t i = 0; i < l.atom.arity; ++i) atom += " " + rule.variables.at(l.atom.args[i]).name;
  atom += ")";
  return l.positive ? atom : "(not " + atom + ")";
}

std::string format_action_pattern(const Domain& domain, const Rule& rule) {
  std::string out = domain.actions.at(rule.action).name + "(";
  for (std::size_t i = 0; i < rule.action_args.size(); ++i)
    out += (i ? ", " : "") + rule.variables.at(rule.action_args[i]).name;
  return out + ")";
}

std::string join_patterns(const Domain& domain, const Rule& rule, const std::vector<LiteralPattern>& ls) {
  std::string out;
  for (const LiteralPattern& l : ls) out += (out.empty() ? "" : " ") + format_pattern(domain, rule, l);
  return out;
}

}  // namespace

std::string format_rule(const Domain& domain, const Rule& rule) {
  std::string out = "If ";
  if (rule.subtask) out += "the subtask is " + *rule.subtask + "\n   AND ";
  out += "the goal is " + join_patterns(domain, rule, rule.goal) + "\n";
  for (const RuleVariable& v : rule.variables) {
    if (v.object_of_interest) out += "   AND " + v.name + " is the object of interest\n";
    if (v.category) out += "   AND category(" + v.name + ") = " + *v.category + "\n";
  }
  for (const LiteralPattern& l : rule.conditions) out += "   AND " + format_pattern(domain, rule, l) + "\n";
  out += "Then:\n   propose action " + format_action_pattern(domain, rule) + " (" +
         std::to_string(rule.steps_to_goal) + (rule.steps_to_goal == 1 ? " step" : " steps") +
         " to the goal)\n";
  return out;
}

std::string rule_signature(const Domain& domain, const Rule& rule) {
  std::string out = format_action_pattern(domain, rule) + " <-";
  if (rule.subtask) out += " subtask=" + *rule.subtask;
  for (const RuleVariable& v : rule.variables) {
    if (v.object_of_interest) out += " interest(" + v.name + ")";
    if (v.category) out += " category(" + v.name + ")=" + *v.category;
  }
  out += " goal{" + join_patterns(domain, rule, rule.goal) + "}";
  out += " state{" + join_patterns(domain, rule, rule.conditions) + "}";
  out += " steps=" + std::to_string(rule.steps_to_goal);
  return out;
}

}  // namespace apprentice
