#include "language/generation.h"

#include <algorithm>

#include "util/text.h"
#include "world/state_lookup.h"

namespace apprentice::language {
namespace {

// Strips final punctuation and spaces: the question supplies its own.
std::string_view bare(std::string_view text) {
  text = trim(text);
  while (!text.empty() && (text.back() == '.' || text.back() == '?' || text.back() == '!')) {
    text.remove_suffix(1);
    text = trim(text);
  }
  return text;
}

// The English of one literal; `object_word` replaces the object of
// interest's noun ("the object") when set.
std::string describe_literal(const World& world, const Literal& literal, std::optional<ObjectId> object,
                             std::string_view object_word) {
  const Vocabulary& v = world.vocabulary;
  const Fact& f = literal.fact;
  auto noun = [&](ObjectId id) {
    return object && *object == id ? std::string(object_word) : noun_for(world, id);
  };
  std::string is = literal.positive ? " is " : " is not ";
  if ((f.predicate == v.in || f.predicate == v.on) && f.arity == 2)
    return noun(f.args[0]) + is + (f.predicate == v.in ? "in " : "on ") + noun(f.args[1]);
  if (f.predicate == v.closed && f.arity == 1) return noun(f.args[0]) + (literal.positive ? " is closed" : " is open");
  if (f.predicate == v.holding && f.arity == 1) return "I am " + std::string(literal.positive ? "" : "not ") + "holding " + noun(f.args[0]);
  if (f.predicate == v.handempty) return literal.positive ? "my hand is empty" : "my hand is full";
  return format_literal(*world.domain, *world.universe, literal);
}

std::string describe_literals(const World& world, const Goal& goal, std::optional<ObjectId> object,
                              std::string_view object_word) {
  std::vector<Literal> ordered = goal.literals;
  const Vocabulary& v = world.vocabulary;
  std::stable_partition(ordered.begin(), ordered.end(), [&](const Literal& l) {
    return l.fact.predicate == v.in || l.fact.predicate == v.on;
  });
  std::vector<std::string> parts;
  for (const Literal& l : ordered) parts.push_back(describe_literal(world, l, object, object_word));
  return join(parts, " and ");
}

std::string category_of(const World& world, ObjectId object) { return world.universe->info(object).category; }

// `text` with the object's kind as a person says it, "ceramic plate", where
// it has the world's name for it, "ceramic-plate" (the LLM's words echo it).
std::string with_spoken_kind(const World& world, ObjectId object, std::string_view text) {
  const std::string category = category_of(world, object), spoken = spoken_category(category);
  std::string out(text);
  if (spoken == category) return out;
  for (auto at = out.find(category); at != std::string::npos; at = out.find(category, at + spoken.size()))
    out.replace(at, category.size(), spoken);
  return out;
}

}  // namespace

std::string spoken_category(std::string_view category) {
  std::string out(category);
  std::replace(out.begin(), out.end(), '-', ' ');
  return out;
}

std::string capitalize(std::string text) {
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z') text[0] = static_cast<char>(text[0] - 'a' + 'A');
  return text;
}

std::string_view article_for(std::string_view word) {
  if (word.empty()) return "a";
  // Spelled with a vowel, said with a consonant: "a unicorn", "a
  // ukulele", "a euro coin", "a one-way valve".
  for (std::string_view sound : {"uni", "use", "usu", "uten", "uku", "eu", "ewe", "one", "once"})
    if (word.starts_with(sound)) return "a";
  // Spelled with a consonant, said with a vowel: "an hour", "an honest".
  for (std::string_view sound : {"hour", "honest", "honor", "honour", "heir"})
    if (word.starts_with(sound)) return "an";
  char c = word.front();
  return (c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u') ? "an" : "a";
}

std::string noun_for(const World& world, ObjectId object) {
  const ObjectInfo& info = world.universe->info(object);
  std::string name = info.category;
  if (info.kind != ObjectKind::kItem) std::replace(name.begin(), name.end(), '-', ' ');
  for (auto word = info.properties.rbegin(); word != info.properties.rend(); ++word) name = *word + " " + name;
  return "the " + name;
}

std::string spoken_category(const World& world, ObjectId object) {
  std::string name = world.universe->info(object).category;
  std::replace(name.begin(), name.end(), '-', ' ');
  return name;
}

bool openable(const World& world, ObjectId id) { return world.state.holds(Fact(world.vocabulary.openable, {id})); }

std::optional<ObjectId> place_of(const World& world, ObjectId object) {
  // The first (on|in object ?p) in the state's order, in O(log n).
  const Vocabulary& v = world.vocabulary;
  const std::optional<Fact> first = first_fact({world.state.facts_of(v.on, 2, object), world.state.facts_of(v.in, 2, object)});
  if (!first) return std::nullopt;
  return first->args[1];
}

namespace {

std::string properties_of(const ObjectInfo& info) { return join(info.properties, " "); }

// Whether the properties tell `object` apart from each of `others`.
bool told_apart_by_properties(const World& world, ObjectId object, const std::vector<ObjectId>& others) {
  const ObjectInfo& mine = world.universe->info(object);
  if (mine.properties.empty()) return false;
  return std::all_of(others.begin(), others.end(), [&](ObjectId other) {
    const auto& theirs = world.universe->info(other).properties;
    return std::any_of(mine.properties.begin(), mine.properties.end(), [&](const std::string& p) {
      return std::find(theirs.begin(), theirs.end(), p) == theirs.end();
    });
  });
}

}  // namespace

std::string distinct_noun_for(const World& world, ObjectId object, std::span<const ObjectId> among) {
  const ObjectInfo& info = world.universe->info(object);
  std::vector<ObjectId> alike;
  for (ObjectId other : among)
    if (other != object && world.universe->info(other).category == info.category) alike.push_back(other);
  std::string name = spoken_category(world, object);
  if (alike.empty()) return "the " + name;
  bool by_properties = told_apart_by_properties(world, object, alike);
  std::string noun = "the " + (info.properties.empty() ? "" : properties_of(info) + " ") + name;
  if (by_properties) return noun;
  auto where = place_of(world, object);
  bool by_place = where && std::none_of(alike.begin(), alike.end(), [&](ObjectId other) {
    return place_of(world, other) == where;
  });
  if (!by_place) return noun;
  const char* preposition = world.universe->info(*where).kind == ObjectKind::kSurface ? " on " : " in ";
  return noun + preposition + distinct_noun_for(world, *where);
}

std::string distinct_noun_for(const World& world, ObjectId object) {
  std::vector<ObjectId> all(world.universe->size());
  for (ObjectId id = 0; id < all.size(); ++id) all[id] = id;
  return distinct_noun_for(world, object, all);
}

std::string say_alternatives(const std::vector<std::string>& options, std::string_view conjunction) {
  if (options.empty()) return "";
  std::string out = options.front();
  for (std::size_t i = 1; i < options.size(); ++i)
    out += (i + 1 == options.size() ? " " + std::string(conjunction) + " " : ", ") + options[i];
  return out;
}

std::string say_which_question(const World& world, std::span<const ObjectId> candidates) {
  std::vector<std::string> options;
  for (ObjectId id : candidates) options.push_back(distinct_noun_for(world, id, candidates));
  bool one_category = !candidates.empty() && std::all_of(candidates.begin(), candidates.end(), [&](ObjectId id) {
    return world.universe->info(id).category == world.universe->info(candidates.front()).category;
  });
  bool by_properties = one_category && std::all_of(candidates.begin(), candidates.end(), [&](ObjectId id) {
    std::vector<ObjectId> others;
    for (ObjectId o : candidates)
      if (o != id) others.push_back(o);
    return told_apart_by_properties(world, id, others);
  });
  if (by_properties) return "Which " + spoken_category(world, candidates.front()) + ": " + say_alternatives(options) + "?";
  return "Which do you mean: " + say_alternatives(options) + "?";
}

std::string location_phrase(const World& world, ObjectId object) {
  auto where = place_of(world, object);
  if (!where) return "";
  return (world.state.holds(Fact(world.vocabulary.on, {object, *where})) ? "on " : "in ") + noun_for(world, *where);
}

std::string say_task_name(std::string_view name) {
  std::string said(bare(name));
  std::replace(said.begin(), said.end(), '-', ' ');  // "tidy exam-room" is said "tidy exam room"
  return capitalize(said) + ".";
}

namespace {

// "on the table", "in the dish rack"; over several places of a category,
// any of them: "in a bag".
std::string at_places(const World& world, std::span<const ObjectId> places) {
  const ObjectInfo& first = world.universe->info(places.front());
  std::string where = first.kind == ObjectKind::kSurface ? "on " : "in ";
  if (places.size() == 1) return where + noun_for(world, places.front());
  std::string name = first.category;
  std::replace(name.begin(), name.end(), '-', ' ');
  return where + std::string(article_for(name)) + " " + name;
}

}  // namespace

std::string say_repeat_while(const World& world, ObjectId place) {
  return say_repeat_while(world, std::span<const ObjectId>(&place, 1));
}

std::string say_repeat_while(const World& world, std::span<const ObjectId> places) {
  return "Repeat the following tasks while an object is " + at_places(world, places) + ".";
}

std::string say_subtask(std::string_view verb, const World& world, ObjectId place) {
  return say_subtask(verb, world, std::span<const ObjectId>(&place, 1));
}

std::string say_subtask(std::string_view verb, const World& world, std::span<const ObjectId> places) {
  return capitalize(std::string(verb)) + " an object that is " + at_places(world, places) + ".";
}

std::string say_done() { return "You are done."; }
std::string say_repeat() { return "Repeat."; }
std::string say_answer(bool yes) { return yes ? "yes." : "no."; }

std::string describe_goal(const World& world, const Goal& goal) {
  return describe_literals(world, goal, std::nullopt, "");
}

std::string describe_goal_instruction(const World& world, ObjectId object, const Goal& goal) {
  std::string category = category_of(world, object);
  return "If the object is " + std::string(article_for(category)) + " " + category +
         " then the goal is that " + describe_literals(world, goal, object, "the object") + ".";
}

std::string describe_action(const World& world, const Action& action) {
  const std::string& schema = world.domain->actions.at(action.schema).name;
  auto args = action.arguments();
  auto arg = [&](std::size_t i) { return i < args.size() ? noun_for(world, args[i]) : std::string("it"); };
  if (schema == "open") return "Open " + arg(0) + ".";
  if (schema == "close") return "Close " + arg(0) + ".";
  if (schema == "pick-up" || schema == "pick-up-from") return "Pick up " + arg(0) + ".";
  if (schema == "put-in") return "Put " + arg(0) + " in " + arg(1) + ".";
  if (schema == "put-on") return "Put " + arg(0) + " on " + arg(1) + ".";
  return capitalize(format_action(*world.domain, *world.universe, action)) + ".";
}

std::string describe_plan(const World& world, std::span<const Action> actions) {
  std::vector<std::string> sentences;
  for (const Action& a : actions) sentences.push_back(describe_action(world, a));
  return join(sentences, " ");
}

std::string say_next_goal_request(std::string_view subtask_verb) {
  return "What is the next goal or subtask of " + std::string(subtask_verb) + "?";
}

std::string say_next_action_request(std::string_view subtask_verb) {
  return "What do I do next for " + std::string(subtask_verb) + "?";
}

std::string say_goal_question(const World& world, ObjectId object, std::string_view goal_statement,
                              bool from_language_model) {
  std::string_view statement = bare(goal_statement);
  constexpr std::string_view kPrefix = "the goal is that ";
  if (starts_with_ignoring_case(statement, kPrefix)) statement.remove_prefix(kPrefix.size());
  const std::string spoken = spoken_category(category_of(world, object));
  const std::string goal = with_spoken_kind(world, object, trim(statement));
  const std::string where = location_phrase(world, object);
  return std::string(from_language_model ? "[LM] " : "") + "For " + std::string(article_for(spoken)) + " " + spoken +
         (where.empty() ? "" : " " + where) + ", is the goal that " + goal + "?";
}

std::string say_goal_question(const World& world, ObjectId object, const Goal& goal, bool from_language_model) {
  return say_goal_question(world, object, describe_goal(world, goal), from_language_model);
}

std::string say_action_question(const World& world, ObjectId object, std::string_view action_text,
                                bool from_language_model) {
  return std::string(from_language_model ? "[LM] " : "") + "For the " + spoken_category(category_of(world, object)) +
         ", should I '" + with_spoken_kind(world, object, bare(action_text)) + "'?";
}

}  // namespace apprentice::language
