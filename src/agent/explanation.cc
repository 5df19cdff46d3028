#include "agent/explanation.h"

#include <algorithm>
#include <optional>
#include <string_view>

#include "language/generation.h"
#include "language/narration.h"
#include "util/text.h"

namespace apprentice {

namespace {

using language::spoken_category;

// A fact about things named in words, in the present tense: "the fridge is
// closed", "I am holding the object".
std::string fact_words(const std::string& predicate, bool positive, const std::vector<std::string>& args) {
  auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : std::string("something"); };
  std::string is = positive ? " is " : " is not ";
  if ((predicate == "in" || predicate == "on") && args.size() == 2) return arg(0) + is + predicate + " " + arg(1);
  if (predicate == "closed") return arg(0) + (positive ? " is closed" : " is open");
  if (predicate == "holding") return std::string("I am ") + (positive ? "" : "not ") + "holding " + arg(0);
  if (predicate == "handempty") return positive ? "my hand is empty" : "my hand is full";
  if (predicate == "openable") return arg(0) + (positive ? " has a door" : " has no door");
  if (predicate == "grabbable") return arg(0) + (positive ? " can be picked up" : " cannot be picked up");
  if (predicate == "receptacle" || predicate == "surface")
    return arg(0) + is + std::string(language::article_for(predicate)) + " " + predicate;
  std::string out = "\"" + spoken_category(predicate) + "\"" + (positive ? " holds" : " does not hold");
  if (!args.empty()) out += " for " + language::list_phrase(args);
  return out;
}

std::vector<std::string> template_arguments(const GoalTemplateLiteral& literal, const std::string& category) {
  std::vector<std::string> args;
  for (const GoalTemplateArgument& a : literal.arguments) {
    if (a.object_of_interest) {
      args.push_back(std::string(language::article_for(category)) + " " + spoken_category(category));
      continue;
    }
    // A look-alike keeps what told it apart: "the top drawer", not "the
    // drawer" when the world had two.
    std::string name = spoken_category(a.category);
    for (auto word = a.properties.rbegin(); word != a.properties.rend(); ++word) name = *word + " " + name;
    args.push_back("the " + name);
  }
  return args;
}

// How the rule's variables are spoken: "the object", "the fridge", "the
// receptacle", "the second receptacle", "the other item".
std::vector<std::string> variable_names(const Rule& rule) {
  std::vector<std::string> names;
  for (const RuleVariable& v : rule.variables) {
    if (v.object_of_interest) {
      names.push_back(v.category ? "the object (" + std::string(language::article_for(*v.category)) + " " +
                                       spoken_category(*v.category) + ")"
                                 : "the object");
      continue;
    }
    if (v.category) {
      names.push_back("the " + spoken_category(*v.category));
      continue;
    }
    std::string base = v.name.size() > 1 && v.name[1] == 'r'   ? "receptacle"
                       : v.name.size() > 1 && v.name[1] == 's' ? "surface"
                                                               : "item";
    bool numbered = v.name.size() > 2;
    std::string name = base == "item" ? "the other item" : "the " + base;
    if (numbered) name = "the " + std::string(base == "item" ? "other item " : base + " ") + v.name.substr(2);
    names.push_back(name);
  }
  return names;
}

std::string pattern_words(const Domain& domain, const LiteralPattern& literal, const std::vector<std::string>& names) {
  std::vector<std::string> args;
  for (std::uint8_t i = 0; i < literal.atom.arity; ++i) args.push_back(names.at(literal.atom.args[i]));
  return fact_words(domain.predicates.at(literal.atom.predicate).name, literal.positive, args);
}

// An action in words, its arguments already spoken: "open the fridge",
// "take the object out of the receptacle".
std::string action_phrase(const std::string& schema, const std::vector<std::string>& args) {
  auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : std::string("it"); };
  if (schema == "open") return "open " + arg(0);
  if (schema == "close") return "close " + arg(0);
  if (schema == "pick-up") return "pick up " + arg(0) + " from " + arg(1);
  if (schema == "pick-up-from") return "take " + arg(0) + " out of " + arg(1);
  if (schema == "put-in") return "put " + arg(0) + " in " + arg(1);
  if (schema == "put-on") return "put " + arg(0) + " on " + arg(1);
  return spoken_category(schema) + (args.empty() ? "" : " " + language::list_phrase(args));
}

std::string action_words(const Domain& domain, const Rule& rule, const std::vector<std::string>& names) {
  std::vector<std::string> args;
  for (VariableId v : rule.action_args) args.push_back(names.at(v));
  return action_phrase(domain.actions.at(rule.action).name, args);
}

// An object's name as a person says it: "diaper-pail1" is "the diaper
// pail" (the number only tells look-alikes apart in files).
std::string spoken_object(std::string_view name) {
  while (!name.empty() && name.back() >= '0' && name.back() <= '9') name.remove_suffix(1);
  while (!name.empty() && name.back() == '-') name.remove_suffix(1);
  return "the " + spoken_category(name);
}

// A grounded action as the learner logs it, "(close diaper-pail1)", in
// words: "close the diaper pail". Text that is no such action is kept.
std::string spoken_action(std::string_view text) {
  std::string_view body = trim(text);
  if (body.size() < 2 || body.front() != '(' || body.back() != ')') return std::string(text);
  std::vector<std::string> words = split_words(body.substr(1, body.size() - 2));
  if (words.empty()) return std::string(text);
  std::vector<std::string> args;
  for (std::size_t i = 1; i < words.size(); ++i) args.push_back(spoken_object(words[i]));
  return action_phrase(words.front(), args);
}

// "ceramic-plate1 (ceramic-plate)", as learning records the object, is "the
// ceramic plate" ("the crackers": a kind, as people name it).
std::string spoken_learned_on(const std::string& object) {
  const auto open = object.rfind(" (");
  if (open != std::string::npos && object.ends_with(")")) {
    std::string category = object.substr(open + 2, object.size() - open - 3);
    return "the " + spoken_category(category);
  }
  return spoken_object(object);
}

// The doors in a reason, "in the fridge (closed fridge)", in words: "in the
// fridge, with the fridge closed" ("(not (closed fridge))": open).
std::string spoken_doors(std::string text) {
  struct Door {
    std::string_view atom, state;
  };
  for (const Door& door : {Door{"(not (closed ", " open"}, Door{"(closed ", " closed"}}) {
    const std::string_view atom = door.atom, state = door.state;
    for (auto at = text.find(atom); at != std::string::npos; at = text.find(atom, at)) {
      const auto end = text.find(')', at);
      if (end == std::string::npos) break;
      std::string place = text.substr(at + atom.size(), end - at - atom.size());
      const std::size_t stop = atom.starts_with("(not") && end + 1 < text.size() && text[end + 1] == ')' ? end + 2 : end + 1;
      const std::string words = "with the " + spoken_category(place) + std::string(state);
      const std::size_t start = at > 0 && text[at - 1] == ' ' ? at - 1 : at;
      const std::string replacement = (start < at ? ", " : "") + words;
      text.replace(start, stop - start, replacement);
      at = start + replacement.size();
    }
  }
  return text;
}

// Where a piece of knowledge came from, as stored ("search: (open
// fridge1)"), in words ("my own search, which chose to open the fridge").
std::string spoken_source(const std::string& source) {
  auto after = [&](std::string_view prefix) -> std::optional<std::string> {
    if (!source.starts_with(prefix)) return std::nullopt;
    return source.substr(prefix.size());
  };
  if (auto said = after("instructor: ")) return "the instructor, who said " + *said;
  if (auto action = after("search: ")) return "my own search, which chose to " + spoken_action(*action);
  if (source == "search") return "my own search";
  if (auto action = after("rule: ")) return "a rule I had learned, which chose to " + spoken_action(*action);
  if (auto said = after("llm: ")) return "the language model, which said " + *said;
  if (auto said = after("corpus: ")) return "recorded language-model answers, which said " + *said;
  if (auto like = after("analogy: ")) return "analogy, " + *like;
  if (auto why = after("decision: ")) return "weighing what I knew: " + spoken_doors(spoken_source(*why));
  if (auto why = after("fleet: ")) return "other households: " + spoken_doors(*why);
  return source;
}

std::string subtask_phrase(const LearnedSubtask& s) {
  return s.verb + " what is " + s.relation + " the " + spoken_category(s.place_category);
}

}  // namespace

std::string explain_task(const TaskKnowledge& task) {
  std::vector<std::string> steps;
  for (const LearnedSubtask& s : task.subtasks) steps.push_back(subtask_phrase(s));
  std::string out = "To " + language::task_phrase(task.name) + ":";
  if (steps.empty()) return out + " nothing is known yet.";
  for (std::size_t i = 0; i < steps.size(); ++i) out += (i == 0 ? " " : ", then ") + steps[i];
  return out + ".";
}

std::string explain_goal(const GoalKnowledge& goal) {
  const GoalKey& key = goal.key;
  // "the ketchup", "the crackers": a kind, as people name what they put away.
  std::string subject = "the " + spoken_category(key.category);
  const bool plural = language::is_plural_category(key.category);
  std::vector<std::string> parts;
  // What becomes of the object comes first, as the agent reads goals back.
  std::vector<GoalTemplateLiteral> ordered = goal.literals;
  std::stable_partition(ordered.begin(), ordered.end(), [](const GoalTemplateLiteral& l) {
    return (l.predicate == "in" || l.predicate == "on") && !l.arguments.empty() && l.arguments[0].object_of_interest;
  });
  for (const GoalTemplateLiteral& l : ordered) {
    std::vector<std::string> args = template_arguments(l, key.category);
    bool about_object = !l.arguments.empty() && l.arguments[0].object_of_interest;
    if ((l.predicate == "in" || l.predicate == "on") && args.size() == 2) {
      std::string where = l.positive ? l.predicate : (l.predicate == "in" ? "out of" : "off");
      parts.push_back((about_object ? subject + (l.positive ? (plural ? " go " : " goes ") : (plural ? " end " : " ends ")) : args[0] + " ends ") + where + " " + args[1]);
    } else if (l.predicate == "closed" && args.size() == 1) {
      parts.push_back(args[0] + " ends " + (l.positive ? "closed" : "open"));
    } else {
      parts.push_back(fact_words(l.predicate, l.positive, args) + " at the end");
    }
  }
  std::string outcome = parts.size() == 2 ? parts[0] + ", and " + parts[1] : language::list_phrase(parts);
  return "When I " + key.subtask + " the " + spoken_category(key.place) + " (to " + language::task_phrase(key.task) +
         "), " + outcome + ".";
}

std::string explain_rule(const Domain& domain, const Rule& rule) {
  std::vector<std::string> names = variable_names(rule);
  std::vector<std::string> goal, state;
  for (const LiteralPattern& l : rule.goal) goal.push_back(pattern_words(domain, l, names));
  for (const LiteralPattern& l : rule.conditions) {
    // "the receptacle is a receptacle" says nothing a person needs.
    const std::string& predicate = domain.predicates.at(l.atom.predicate).name;
    if (l.positive && (predicate == "receptacle" || predicate == "surface")) continue;
    state.push_back(pattern_words(domain, l, names));
  }
  std::string out = rule.subtask ? "While I " + *rule.subtask + ", when" : "When";
  out += " the goal is that " + join(goal, " and ");
  if (!state.empty()) out += ", and " + language::list_phrase(state);
  out += ": " + action_words(domain, rule, names) + " (" + language::count_phrase(rule.steps_to_goal, "step") +
         " from the goal).";
  return language::capitalize(out);
}

std::string explain_source(const std::string& source) { return spoken_source(source); }

std::string explain_provenance(const Provenance& provenance) {
  return "learned on " + spoken_learned_on(provenance.object) + " from " + spoken_source(provenance.source);
}

}  // namespace apprentice
