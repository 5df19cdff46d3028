#include "language/narration.h"

#include <algorithm>
#include <array>
#include <set>
#include <variant>

#include "language/generation.h"
#include "language/utterance.h"
#include "util/text.h"
#include "world/state_lookup.h"

namespace apprentice::language {
namespace {

bool plural_name(const World& world, ObjectId object) {
  return is_plural_category(world.universe->info(object).category);
}

// A clause whose noun phrases are still objects, so that one already
// mentioned can become "it".
struct SpokenClause {
  std::vector<std::variant<std::string, ObjectId>> parts;
  // Things of the first thing's name done the same way with it, said with
  // it as one ("two gardening gloves"); see report_actions.
  std::vector<ObjectId> along;

  SpokenClause& word(std::string w) {
    parts.emplace_back(std::move(w));
    return *this;
  }
  SpokenClause& thing(ObjectId o) {
    parts.emplace_back(o);
    return *this;
  }
  std::optional<ObjectId> last_thing() const {
    for (auto it = parts.rbegin(); it != parts.rend(); ++it)
      if (const ObjectId* o = std::get_if<ObjectId>(&*it)) return *o;
    return std::nullopt;
  }
  std::optional<ObjectId> first_thing() const {
    for (const auto& part : parts)
      if (const ObjectId* o = std::get_if<ObjectId>(&part)) return *o;
    return std::nullopt;
  }
  bool mentions(ObjectId o) const {
    return std::any_of(parts.begin(), parts.end(), [&](const auto& p) {
      const ObjectId* id = std::get_if<ObjectId>(&p);
      return id && *id == o;
    });
  }
  // What "it" can stand for in this clause after `previous`: the last thing
  // `previous` named, else the first, if this clause names it too.
  std::optional<ObjectId> pronoun_after(const SpokenClause& previous) const {
    for (auto candidate : {previous.last_thing(), previous.first_thing()})
      if (candidate && mentions(*candidate)) return candidate;
    return std::nullopt;
  }
  // The words, with the first mention of `it` (if any) said as "it".
  std::string render(const World& world, std::optional<ObjectId> it = std::nullopt) const {
    std::vector<std::string> words;
    bool pronoun_used = false;
    for (const auto& part : parts) {
      if (const std::string* w = std::get_if<std::string>(&part)) {
        words.push_back(*w);
      } else {
        ObjectId o = std::get<ObjectId>(part);
        if (!along.empty() && first_thing() == o) {
          std::vector<ObjectId> together{o};
          together.insert(together.end(), along.begin(), along.end());
          words.push_back(spoken_things(world, together));
        } else if (it && *it == o && !pronoun_used) {
          std::string pronoun = object_pronoun(world, o);
          // A pronoun goes before the particle of a phrasal verb: "picked it up".
          const std::string suffix = " up";
          if (!words.empty() && words.back().size() > suffix.size() &&
              words.back().compare(words.back().size() - suffix.size(), suffix.size(), suffix) == 0) {
            words.back().insert(words.back().size() - suffix.size(), " " + pronoun);
          } else {
            words.push_back(pronoun);
          }
          pronoun_used = true;
        } else {
          words.push_back(spoken_name(world, o));
        }
      }
    }
    return join(words, " ");
  }
};

bool is_placement(const World& world, const Fact& f) {
  return (f.predicate == world.vocabulary.in || f.predicate == world.vocabulary.on) && f.arity == 2;
}

std::string predicate_words(const World& world, PredicateId predicate) {
  return spoken_category(world.domain->predicates.at(predicate).name);
}

// "the ketchup is in the fridge" with `be` = {"is", "is not"} or {"should
// be", "should not be"}.
std::string fact_sentence(const World& world, const Literal& literal, std::string_view be, std::string_view be_not) {
  const Vocabulary& v = world.vocabulary;
  const Fact& f = literal.fact;
  std::string is = " " + std::string(literal.positive ? be : be_not) + " ";
  if (be == "is" && f.arity > 0 && plural_name(world, f.args[0]))
    is = literal.positive ? " are " : " are not ";
  if (is_placement(world, f))
    return spoken_name(world, f.args[0]) + is + (f.predicate == v.in ? "in " : "on ") + spoken_name(world, f.args[1]);
  if (f.predicate == v.closed && f.arity == 1) return spoken_name(world, f.args[0]) + " " + std::string(be) + (literal.positive ? " closed" : " open");
  if (f.predicate == v.holding && f.arity == 1) {
    std::string am = be == "is" ? "am" : std::string(be);
    return "I " + am + (literal.positive ? " " : " not ") + "holding " + spoken_name(world, f.args[0]);
  }
  if (f.predicate == v.handempty) return std::string("my hand ") + std::string(be) + (literal.positive ? " empty" : " full");
  // The domain's adjectives a person would not use, as noun phrases that
  // read after every form of "be".
  if (f.predicate == v.openable && f.arity == 1) return spoken_name(world, f.args[0]) + is + "something with a door";
  if (f.predicate == v.grabbable && f.arity == 1) return spoken_name(world, f.args[0]) + is + "something I can pick up";
  std::string words = predicate_words(world, f.predicate);
  if (f.arity == 0) return "it" + is + words;
  std::string out = spoken_name(world, f.args[0]) + is + words;
  for (std::uint16_t i = 1; i < f.arity; ++i) out += (i == 1 ? " " : " and ") + spoken_name(world, f.args[i]);
  return out;
}

std::vector<Literal> placements_first(const World& world, const Goal& goal) {
  std::vector<Literal> ordered = goal.literals;
  std::stable_partition(ordered.begin(), ordered.end(),
                        [&](const Literal& l) { return is_placement(world, l.fact); });
  return ordered;
}

// "goes in the fridge" / "ends closed": one literal as an outcome.
std::string outcome(const World& world, ObjectId object, const Literal& literal, std::string_view subject) {
  const Vocabulary& v = world.vocabulary;
  const Fact& f = literal.fact;
  if (is_placement(world, f)) {
    std::string where = (f.predicate == v.in ? "in " : "on ") + spoken_name(world, f.args[1]);
    if (!literal.positive) where = (f.predicate == v.in ? "out of " : "off ") + spoken_name(world, f.args[1]);
    if (f.args[0] == object) {
      bool plural = plural_name(world, object) && subject != "it";
      if (subject == "they") plural = true;
      return std::string(subject) + (literal.positive ? (plural ? " go " : " goes ") : (plural ? " end " : " ends ")) +
             where;
    }
    return spoken_name(world, f.args[0]) + " ends " + where;
  }
  if (f.predicate == v.closed && f.arity == 1)
    return spoken_name(world, f.args[0]) + " ends " + (literal.positive ? "closed" : "open");
  if (f.predicate == v.holding && f.arity == 1)
    return std::string("I end up ") + (literal.positive ? "" : "not ") + "holding " + spoken_name(world, f.args[0]);
  if (f.predicate == v.handempty) return std::string("my hand ends ") + (literal.positive ? "empty" : "full");
  return fact_sentence(world, literal, "is", "is not") + " at the end";
}

std::string join_outcomes(const std::vector<std::string>& parts) {
  if (parts.size() == 2) return parts[0] + ", and " + parts[1];
  return list_phrase(parts);
}

bool is_vowel(char c) { return c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u'; }

// "opened", "put", "wiped": the past tense of a verb, for reports.
std::string past_tense(const std::string& verb) {
  static const std::pair<const char*, const char*> kIrregular[] = {
      {"put", "put"},     {"set", "set"},     {"take", "took"},   {"throw", "threw"}, {"get", "got"},
      {"hang", "hung"},   {"make", "made"},   {"sweep", "swept"}, {"feed", "fed"},    {"shut", "shut"},
      {"cut", "cut"},     {"bring", "brought"}, {"lay", "laid"},  {"hold", "held"},   {"give", "gave"}};
  for (const auto& [base, past] : kIrregular)
    if (verb == base) return past;
  if (verb.empty()) return verb;
  if (verb.back() == 'e') return verb + "d";
  if (verb.size() > 1 && verb.back() == 'y' && !is_vowel(verb[verb.size() - 2]))
    return verb.substr(0, verb.size() - 1) + "ied";
  return verb + "ed";
}

std::string schema_name(const World& world, const Action& action) {
  return world.domain->actions.at(action.schema).name;
}

// The action as a clause, in the past tense (`past`) or as a command.
SpokenClause action_clause(const World& world, const Action& action, bool past) {
  const std::string schema = schema_name(world, action);
  auto args = action.arguments();
  SpokenClause c;
  if (schema == "open" && args.size() == 1) return c.word(past ? "opened" : "open").thing(args[0]);
  if (schema == "close" && args.size() == 1) return c.word(past ? "closed" : "close").thing(args[0]);
  if (schema == "pick-up" && !args.empty()) return c.word(past ? "picked up" : "pick up").thing(args[0]);
  if (schema == "pick-up-from" && args.size() == 2)
    return c.word(past ? "took" : "take").thing(args[0]).word("out of").thing(args[1]);
  if ((schema == "put-in" || schema == "put-on") && args.size() == 2)
    return c.word("put").thing(args[0]).word(schema == "put-in" ? "in" : "on").thing(args[1]);
  std::vector<std::string> words = split_words(spoken_category(schema));
  if (past && !words.empty()) words[0] = past_tense(words[0]);
  c.word(join(words, " "));
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0) c.word("and");
    c.thing(args[i]);
  }
  return c;
}

// Why a precondition fails, as a clause about the things involved.
SpokenClause failed_precondition(const World& world, const State& state, const Literal& literal) {
  const Vocabulary& v = world.vocabulary;
  const Fact& f = literal.fact;
  SpokenClause c;
  if (f.predicate == v.holding && f.arity == 1 && literal.positive) return c.word("I am not holding").thing(f.args[0]);
  if (f.predicate == v.handempty && literal.positive) {
    for (const Fact& held : state.facts_of(v.holding))
      if (held.predicate == v.holding && held.arity == 1) return c.word("I am holding").thing(held.args[0]);
    return c.word("my hand is not empty");
  }
  if (f.predicate == v.closed && f.arity == 1)
    return c.thing(f.args[0]).word(literal.positive ? "is already open" : "is closed");
  if (f.predicate == v.openable && f.arity == 1) return c.thing(f.args[0]).word("has no door");
  if (f.predicate == v.grabbable && f.arity == 1) return c.thing(f.args[0]).word("cannot be picked up");
  if (f.predicate == v.surface && f.arity == 1) return c.thing(f.args[0]).word("is not something to put things on");
  if (f.predicate == v.receptacle && f.arity == 1) return c.thing(f.args[0]).word("is not something to put things in");
  if (is_placement(world, f)) {
    std::string where = f.predicate == v.in ? "in" : "on";
    return c.thing(f.args[0]).word(literal.positive ? "is not " + where : "is already " + where).thing(f.args[1]);
  }
  return c.word("it is not so that " + fact_sentence(world, literal, "is", "is not"));
}

// "the table is not a receptacle place".
SpokenClause not_of_type(const World& world, ObjectId object, TypeId type) {
  const std::string& name = world.domain->types.at(type).name;
  return SpokenClause().thing(object).word("is not " + std::string(article_for(name)) + " " + spoken_category(name));
}

// Why one action cannot make a literal hold, as a clause.
SpokenClause blocker_clause(const World& world, const UnreachableBlocker& blocker) {
  using Kind = UnreachableBlocker::Kind;
  switch (blocker.kind) {
    case Kind::kWrongType: return not_of_type(world, blocker.object, blocker.type);
    case Kind::kStaticPrecondition: return failed_precondition(world, world.state, blocker.precondition);
    case Kind::kPreconditionNeverHolds:
      return SpokenClause().word("for that, " + fact_sentence(world, blocker.precondition, "would have to be",
                                                        "would have to stop being"));
    case Kind::kNoObjectFits: break;
  }
  return SpokenClause().word("no other object here fits the action \"" + world.domain->actions.at(blocker.schema).name + "\"");
}

// "The garbage will never be closed: it has no door, so I cannot close it."
// ("will": in "the garbage can never be closed", "garbage can" reads as a
// noun.)
std::string never_holds_sentence(const World& world, const UnreachableLiteral& u) {
  const Literal& l = u.literal;
  std::string head = capitalize(fact_sentence(world, l, "will never be", "will never stop being"));
  if (u.reason == UnreachableLiteral::Reason::kNoAction)
    return head + ": nothing I can do " + (l.positive ? "makes that so." : "undoes that.");
  // One reason per distinct clause, with the first action it rules out that
  // the goal names whole ("so I cannot close it").
  std::vector<std::string> reasons, said;
  std::vector<bool> has_action;
  for (const UnreachableBlocker& b : u.blockers) {
    SpokenClause reason = blocker_clause(world, b);
    const bool about_subject = l.fact.arity > 0 && reason.first_thing() == l.fact.args[0];
    std::string text = about_subject ? reason.render(world, l.fact.args[0]) : reason.render(world);
    auto known = std::find(reasons.begin(), reasons.end(), text);
    const auto index = static_cast<std::size_t>(known - reasons.begin());
    if (known == reasons.end()) {
      reasons.push_back(text);
      said.push_back(text);
      has_action.push_back(false);
    }
    const bool rules_out = b.kind == UnreachableBlocker::Kind::kWrongType ||
                           b.kind == UnreachableBlocker::Kind::kStaticPrecondition;
    if (b.action && rules_out && !has_action[index]) {
      said[index] += ", so I cannot " + action_clause(world, *b.action, false).render(world, reason.first_thing());
      has_action[index] = true;
    }
  }
  return head + ": " + list_phrase(said) + ".";
}

}  // namespace

// --- Words -------------------------------------------------------------------

bool is_plural_category(std::string_view category) {
  if (category.size() < 3 || category.back() != 's') return false;
  char before = category[category.size() - 2];
  return before != 's' && before != 'u' && before != 'i';
}

std::string kind_goes(std::string_view category) {
  return "the " + spoken_category(category) + (is_plural_category(category) ? " go" : " goes");
}

std::string plural_noun(std::string_view noun) {
  std::string out(noun);
  if (out.empty()) return out;
  auto ends = [&](std::string_view tail) { return out.size() > tail.size() && out.ends_with(tail); };
  if (ends("s") || ends("x") || ends("z") || ends("ch") || ends("sh")) return out + "es";
  if (ends("y") && std::string_view("aeiou").find(out[out.size() - 2]) == std::string_view::npos)
    return out.substr(0, out.size() - 1) + "ies";
  if (ends("lf")) return out.substr(0, out.size() - 1) + "ves";
  if (ends("fe")) return out.substr(0, out.size() - 2) + "ves";
  return out + "s";
}

std::string spoken_plural(std::string_view category) {
  std::string spoken = spoken_category(category);
  if (is_plural_category(category)) return spoken;
  std::size_t last = spoken.rfind(' ');
  std::size_t start = last == std::string::npos ? 0 : last + 1;
  return spoken.substr(0, start) + plural_noun(std::string_view(spoken).substr(start));
}

std::string spoken_things(const World& world, std::span<const ObjectId> things) {
  // Names in order of first mention, each with how often it was said.
  std::vector<std::pair<std::string, std::vector<ObjectId>>> named;
  for (ObjectId thing : things) {
    std::string name = spoken_name(world, thing);
    auto same = std::find_if(named.begin(), named.end(), [&](const auto& n) { return n.first == name; });
    if (same == named.end()) named.push_back({std::move(name), {thing}});
    else same->second.push_back(thing);
  }
  static constexpr std::array<std::string_view, 11> kNumbers = {"no",  "one", "two", "three", "four", "five",
                                                                "six", "seven", "eight", "nine", "ten"};
  std::vector<std::string> phrases;
  for (const auto& [name, objects] : named) {
    if (objects.size() == 1) {
      phrases.push_back(name);
      continue;
    }
    const ObjectInfo& info = world.universe->info(objects.front());
    std::string count = objects.size() < kNumbers.size() ? std::string(kNumbers[objects.size()])
                                                         : std::to_string(objects.size());
    // "the red cup" twice is "two red cups": the name without "the",
    // its kind in the plural.
    std::string words = name.substr(4);
    std::string singular = spoken_category(info.category);
    if (words.ends_with(singular)) words = words.substr(0, words.size() - singular.size()) + spoken_plural(info.category);
    phrases.push_back(count + " " + words);
  }
  return list_phrase(phrases);
}

std::string spoken_name(const World& world, ObjectId object) {
  const ObjectInfo& info = world.universe->info(object);
  std::string name = spoken_category(info.category);
  if (!info.properties.empty() && world.universe->with_category(info.category).size() > 1)
    name = join(info.properties, " ") + " " + name;
  return "the " + name;
}

std::string spoken_location(const World& world, ObjectId object) {
  // The first of (on object ?p), (in object ?p) and (holding object) in the
  // state's order, each found in O(log n).
  const Vocabulary& v = world.vocabulary;
  const std::optional<Fact> first = first_fact({world.state.facts_of(v.on, 2, object),
                                                world.state.facts_of(v.in, 2, object),
                                                world.state.facts_of(v.holding, 1, object)});
  if (!first) return "";
  if (first->predicate == v.holding && first->arity == 1) return "in my hand";
  return (first->predicate == v.on ? "on " : "in ") + spoken_name(world, first->args[1]);
}

std::string spoken_name_and_location(const World& world, ObjectId object) {
  std::string where = spoken_location(world, object);
  return spoken_name(world, object) + (where.empty() ? "" : " " + where);
}

std::string spoken_places(const World& world, std::span<const ObjectId> places) {
  if (places.size() == 1) return spoken_name(world, places[0]);
  if (!places.empty()) {
    const std::string& category = world.universe->info(places[0]).category;
    bool one_category = std::all_of(places.begin(), places.end(), [&](ObjectId p) {
      return world.universe->info(p).category == category;
    });
    // "the buckets": read in every sentence the agent says of places ("in
    // every bucket" was wrong after "nothing left").
    if (one_category && world.universe->with_category(category).size() == places.size())
      return "the " + spoken_plural(category);
  }
  std::vector<std::string> names;
  for (ObjectId p : places) names.push_back(spoken_name(world, p));
  return list_phrase(names);
}

std::string object_pronoun(const World& world, ObjectId object) { return plural_name(world, object) ? "them" : "it"; }

std::string_view relation_word(const World& world, ObjectId place) {
  return world.universe->info(place).kind == ObjectKind::kSurface ? "on" : "in";
}

std::string task_phrase(std::string_view task_name) {
  static const std::set<std::string> kParticles = {"up", "away", "out", "off", "down"};
  // "tidy exam-room": a location's hyphen is said as a space, as a name's.
  std::string said(task_name);
  std::replace(said.begin(), said.end(), '-', ' ');
  std::vector<std::string> words = split_words(said);
  if (words.size() < 2) return join(words, " ");
  std::size_t object_start = kParticles.count(words[1]) && words.size() > 2 ? 2 : 1;
  // "clean up after party" -> "clean up after the party".
  static const std::set<std::string> kPrepositions = {"after", "before", "around", "for", "with"};
  if (kPrepositions.count(words[object_start]) && words.size() > object_start + 1) ++object_start;
  if (is_determiner(words[object_start])) return join(words, " ");
  words.insert(words.begin() + static_cast<std::ptrdiff_t>(object_start), "the");
  return join(words, " ");
}

std::string count_phrase(long long n, std::string_view singular, std::string_view plural) {
  std::string many = plural.empty() ? std::string(singular) + "s" : std::string(plural);
  return std::to_string(n) + " " + (n == 1 ? std::string(singular) : many);
}

std::string list_phrase(const std::vector<std::string>& items) {
  if (items.empty()) return "";
  if (items.size() == 1) return items[0];
  if (items.size() == 2) return items[0] + " and " + items[1];
  std::string out;
  for (std::size_t i = 0; i + 1 < items.size(); ++i) out += items[i] + ", ";
  return out + "and " + items.back();
}

// --- Questions ---------------------------------------------------------------

std::string ask_task() { return "What task should I learn?"; }

std::string ask_task_step(std::string_view task_name, bool first) {
  return std::string("What should I do ") + (first ? "first" : "next") + " to " + task_phrase(task_name) + "?";
}

std::string ask_goal(const World& world, ObjectId object) {
  return "Where should " + spoken_name_and_location(world, object) + " go?";
}

std::string ask_subtask_end(std::string_view verb, const World& world, std::span<const ObjectId> places) {
  std::string where = places.empty() ? "" : " " + std::string(relation_word(world, places[0])) + " " + spoken_places(world, places);
  return "Is there more to " + std::string(verb) + where + ", or is that all?";
}

std::string ask_leave_the_rest(const World& world, std::span<const ObjectId> things, std::span<const ObjectId> places) {
  const bool one = things.size() == 1;
  std::string where = places.empty() ? std::string() : " " + std::string(relation_word(world, places.front())) + " " +
                                                          spoken_places(world, places);
  return std::string(one ? "There is still 1 thing" : "There are still " + std::to_string(things.size()) + " things") +
         where + ": " + spoken_things(world, things) + ". Shall I leave " +
         (one ? object_pronoun(world, things.front()) : std::string("them")) + "?";
}

std::string read_back_part_left(const World& world, std::span<const ObjectId> things,
                                std::span<const ObjectId> places) {
  std::string where = places.empty() ? std::string() : " " + std::string(relation_word(world, places.front())) + " " +
                                                          spoken_places(world, places);
  return "So I leave " + spoken_things(world, things) + where + ", and this part of the task is done.";
}

std::string read_back_going_on(const World& world, ObjectId object) {
  return "So I go on with " + spoken_name(world, object) + ".";
}

std::string ask_next_action(const World& world, const Goal& goal) {
  return "What should I do next so that " + goal_facts(world, goal) + "?";
}

// --- Goals -------------------------------------------------------------------

std::string goal_facts(const World& world, const Goal& goal) {
  std::vector<std::string> parts;
  for (const Literal& l : placements_first(world, goal)) parts.push_back(fact_sentence(world, l, "is", "is not"));
  return join(parts, " and ");
}

std::string goal_outcome(const World& world, ObjectId object, const Goal& goal, std::string_view subject) {
  std::vector<Literal> ordered = placements_first(world, goal);
  // What becomes of the object itself comes first.
  std::stable_partition(ordered.begin(), ordered.end(), [&](const Literal& l) {
    return is_placement(world, l.fact) && l.fact.args[0] == object;
  });
  std::vector<std::string> parts;
  for (const Literal& l : ordered) parts.push_back(outcome(world, object, l, subject));
  return join_outcomes(parts);
}

std::string read_back_goal(const World& world, ObjectId object, const Goal& goal) {
  return "So " + goal_outcome(world, object, goal, spoken_name(world, object)) + ".";
}

std::string closing_norm_note() {
  return "I close what I open; say \"leave it open\" when something should stay open.";
}

std::string announce_known_goal(const World& world, ObjectId object, const Goal& goal) {
  return "Next, " + spoken_name_and_location(world, object) + ": " +
         goal_outcome(world, object, goal, plural_name(world, object) ? "they" : "it") + ".";
}

std::string expected_fact(const World& world, const Literal& literal) {
  return fact_sentence(world, literal, "should be", "should not be");
}

// --- What was done -------------------------------------------------------------

// Whether `next` does to its first thing what `clause` does to its own,
// the two things having one name: "put the gardening glove on the right
// hook", twice.
bool done_alike(const World& world, const SpokenClause& clause, const SpokenClause& next) {
  if (clause.parts.size() != next.parts.size()) return false;
  std::optional<ObjectId> first = clause.first_thing();
  std::optional<ObjectId> other = next.first_thing();
  if (!first || !other || *first == *other || spoken_name(world, *first) != spoken_name(world, *other)) return false;
  bool first_seen = false;
  for (std::size_t i = 0; i < clause.parts.size(); ++i) {
    const ObjectId* a = std::get_if<ObjectId>(&clause.parts[i]);
    if (a != nullptr && !first_seen) {
      first_seen = true;
      if (std::get_if<ObjectId>(&next.parts[i]) == nullptr) return false;
      continue;
    }
    if (clause.parts[i] != next.parts[i]) return false;
  }
  return true;
}

// Things of one name done alike in a row are said once: "I put two
// gardening gloves on the right hook", not "I put the gardening glove on
// the right hook and put the gardening glove on it".
std::vector<SpokenClause> said_together(const World& world, std::vector<SpokenClause> clauses) {
  std::vector<SpokenClause> out;
  for (SpokenClause& clause : clauses) {
    if (!out.empty() && done_alike(world, out.back(), clause)) {
      out.back().along.push_back(*clause.first_thing());
      continue;
    }
    out.push_back(std::move(clause));
  }
  return out;
}

std::string report_actions(const World& world, std::span<const Action> actions) {
  std::vector<SpokenClause> clauses;
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const Action& a = actions[i];
    // Picking up from a surface and then putting down is one step to say.
    if (schema_name(world, a) == "pick-up" && i + 1 < actions.size()) {
      const Action& next = actions[i + 1];
      std::string next_schema = schema_name(world, next);
      if ((next_schema == "put-in" || next_schema == "put-on") && next.arity > 0 && a.arity > 0 &&
          next.args[0] == a.args[0])
        continue;
    }
    clauses.push_back(action_clause(world, a, true));
  }
  if (clauses.empty()) return "";
  clauses = said_together(world, std::move(clauses));
  std::vector<std::string> said;
  const SpokenClause* previous = nullptr;
  for (const SpokenClause& c : clauses) {
    said.push_back(c.render(world, previous ? c.pronoun_after(*previous) : std::nullopt));
    previous = &c;
  }
  return "I " + list_phrase(said) + ".";
}

std::string action_phrase(const World& world, const Action& action) {
  return action_clause(world, action, false).render(world);
}

std::string plan_steps(const World& world, std::span<const Action> plan) {
  World now = world;
  std::string out;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    out += std::to_string(i + 1) + ". " + capitalize(action_phrase(now, plan[i])) + ".\n";
    now.state = apply(*now.domain, now.state, plan[i]);
  }
  return out;
}

std::string refusal(const World& world, const Action& action) {
  const Domain& domain = *world.domain;
  if (!why_not_applicable(domain, *world.universe, world.state, action)) return "";
  SpokenClause reason;
  bool found = false;
  const ActionSchema& schema = domain.actions.at(action.schema);
  for (std::size_t i = 0; i < action.arity && i < schema.parameters.size(); ++i) {
    TypeId type = world.universe->info(action.args[i]).type;
    if (!domain.is_subtype(type, schema.parameters[i].type)) {
      reason = not_of_type(world, action.args[i], schema.parameters[i].type);
      found = true;
      break;
    }
  }
  if (!found) {
    for (const Literal& l : preconditions_of(domain, action)) {
      if (world.state.satisfies(l)) continue;
      reason = failed_precondition(world, world.state, l);
      found = true;
      break;
    }
  }
  SpokenClause act = action_clause(world, action, false);
  if (!found) return "I cannot " + act.render(world) + ".";
  // "it" stands for what the reason is about.
  return capitalize(reason.render(world)) + ", so I cannot " + act.render(world, reason.first_thing()) + ".";
}

std::string never_holds(const World& world, const UnreachableChain& chain) {
  std::vector<std::string> sentences;
  for (const UnreachableLiteral& u : chain) sentences.push_back(never_holds_sentence(world, u));
  return join(sentences, " ");
}

}  // namespace apprentice::language
