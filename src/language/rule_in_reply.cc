// Whether a reply states a person's rule (language/rule_in_reply.h).
#include "language/rule_in_reply.h"

#include <algorithm>

#include "language/reference.h"
#include "language/reply_acts_parts.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

bool is_general_head(std::string_view head) {
  return is_one_of(head, {"item", "thing", "object", "stuff", "product", "good", "one", "article", "belonging"});
}

std::optional<std::string> category_named(const Lexicon& lexicon, const World& world, std::string_view phrase) {
  NounPhrase noun{"", split_words(to_lower(phrase))};
  if (noun.words.empty()) return std::nullopt;
  if (noun.words.front() == "the" || noun.words.front() == "a" || noun.words.front() == "an") {
    noun.article = noun.words.front();
    noun.words.erase(noun.words.begin());
  }
  if (noun.words.empty()) return std::nullopt;
  ReferenceContext context{world, lexicon, std::nullopt};
  auto resolved = resolve_category(noun, context);
  if (const std::string* category = std::get_if<std::string>(&resolved)) return *category;
  return std::nullopt;
}

std::optional<std::string> other_name_of_asked(const Grounder& grounder, const World& world, std::string_view text,
                                               const Reply& reply, const ReplyContext& context) {
  if (context.asked != Asked::kGoal || !context.object || !std::holds_alternative<Unusable>(reply))
    return std::nullopt;
  auto rule = read_rule(world, grounder.lexicon(), text, context.object);
  if (!rule || rule->clauses.size() != 1) return std::nullopt;
  const RuleClause& clause = rule->clauses.front();
  if (clause.thing || clause.places.empty() || clause.classes.size() != 1) return std::nullopt;
  // One word, in the singular, that names nothing here: a class is said in
  // the plural ("toys go in the basket"), the thing asked about in the
  // singular.
  const RuleClass& said = clause.classes.front();
  if (said.rest || said.phrase.empty() || said.phrase != said.head || !said.modifiers.empty() ||
      is_general_head(said.head))
    return std::nullopt;
  if (singular_forms(said.phrase).size() != 1) return std::nullopt;
  if (category_named(grounder.lexicon(), world, said.phrase).has_value()) return std::nullopt;
  return said.phrase;
}

namespace {

// "go", "belong", "live", "stay", "are kept": words that say where things
// go, which a step ("start with the stuff on the floor") does not.
bool says_things_go(std::string_view text) {
  const std::vector<std::string> words = split_words(to_lower(text));
  return std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return is_verb_of_going(w) || is_one_of(w, {"stay", "stays", "kept"});
  });
}

// Whether every modifier is a property some thing of `kind` has here ("clean
// diapers", where the world's diapers are clean or dirty): the world's
// things picked by what it models, not a class of its own.
bool modifiers_are_properties(const World& world, const std::string& kind, const std::vector<std::string>& modifiers) {
  if (modifiers.empty()) return false;
  const std::vector<ObjectId> things = world.universe->with_category(kind);
  return std::all_of(modifiers.begin(), modifiers.end(), [&](const std::string& modifier) {
    return std::any_of(things.begin(), things.end(), [&](ObjectId o) {
      const std::vector<std::string>& properties = world.universe->info(o).properties;
      return std::find(properties.begin(), properties.end(), modifier) != properties.end();
    });
  });
}

// Whether a class said is one of its own, not the world's kind said in the
// plural ("plates" for the plate). A word that the reference resolves to
// one kind only through WordNet ("clothes" to the dress: not a word of its
// name) is a class all the same. `understood`: the reply's own reading
// could use it.
bool a_class_of_its_own(const Lexicon& lexicon, const World& world, const RuleClass& c, bool understood) {
  if (c.rest) return true;
  if (c.phrase.empty() || (is_general_head(c.head) && c.modifiers.empty())) return false;
  if (is_general_head(c.head)) return true;
  const std::optional<std::string> kind = category_named(lexicon, world, c.phrase);
  if (!kind) return true;
  if (!understood && c.phrase != c.head && !modifiers_are_properties(world, *kind, c.modifiers)) return true;
  std::string name = *kind;
  std::replace(name.begin(), name.end(), '-', ' ');
  const std::vector<std::string> words = split_words(name);
  return std::find(words.begin(), words.end(), c.head) == words.end();
}

}  // namespace

std::optional<RuleReading> rule_in_reply(const Grounder& grounder, const World& world, std::string_view text,
                                         const Reply& reply, const ReplyContext& context) {
  // The thing asked about called by another word is not a class.
  if (other_name_of_asked(grounder, world, text, reply, context)) return std::nullopt;
  // "there": the place named last, or the place a proposal asked about
  // ("yep. hats and caps go there too").
  std::optional<ObjectId> there = context.recent_place;
  if (context.proposal && context.object)
    if (auto proposed = acts::destination(world, GoalGiven{*context.proposal, {}})) there = proposed;
  auto rule = read_rule(world, grounder.lexicon(), text, context.object, there);
  if (!rule || !rule->has_class_clause()) return std::nullopt;
  const auto* unusable = std::get_if<Unusable>(&reply);
  const bool understood = unusable == nullptr;
  // A class that is only the world's kinds named in the plural ("plates and
  // forks go in the dishwasher") is the reply's ordinary reading, where it
  // has one; where it has none ("pots go on the right shelf", said when
  // asked for a part of the task), it says where every such thing goes. So
  // is "an object" ("Repeat the following tasks while an object is on the
  // table").
  std::size_t class_clauses = 0;
  bool rest = false;
  for (const RuleClause& clause : rule->clauses) {
    if (clause.thing) continue;
    if (std::any_of(clause.classes.begin(), clause.classes.end(),
                    [&](const RuleClass& c) { return a_class_of_its_own(grounder.lexicon(), world, c, understood); }))
      ++class_clauses;
    rest = rest || std::any_of(clause.classes.begin(), clause.classes.end(), [](const auto& c) { return c.rest; });
  }
  if (class_clauses == 0) return std::nullopt;
  // What the reply's own reading takes ("tools go in the top drawer": each
  // tool's goal) is left to it, unless the rule says more than one clause or
  // "other".
  // An unusable reply that asks what to do with the things at a place
  // ("start with the stuff on the floor": "What should I do with the things
  // on the floor?") is understood as far as it goes: a step, not a rule;
  // unless it says things go there ("ribbons go in the tub", of a kind
  // not here: where such things go).
  if (unusable != nullptr && !unusable->topic_places.empty() && !says_things_go(text)) return std::nullopt;
  // (A yes or a no whose rest is no goal of the thing asked about takes no
  // class: "yep. hats go there too" is a rule; "no, shoes go in the
  // wardrobe", asked about the sneaker, is the sneaker's goal.)
  const auto* yes_no = std::get_if<YesNo>(&reply);
  const bool rest_answers = yes_no == nullptr || (context.object && goal_in_rest(grounder, world, context, *yes_no));
  if (understood && class_clauses < 2 && !rest && rest_answers) return std::nullopt;
  return rule;
}

}  // namespace apprentice::language
