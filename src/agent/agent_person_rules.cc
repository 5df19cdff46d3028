// A person's rules in the session: said at any question
// (language/rule_reader.h), kept, read back.
#include <algorithm>
#include <cctype>

#include "agent/class_rule_knowledge.h"
#include "agent/goal_repair.h"
#include "agent/person_rule.h"
#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "language/narration_steps.h"
#include "language/utterance.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// `text` with each whole word `word` (ignoring case) said as `instead`.
std::string with_word_replaced(const std::string& text, const std::string& word, const std::string& instead) {
  auto is_word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '\''; };
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!is_word_char(text[i])) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && is_word_char(text[end])) ++end;
    std::string piece = text.substr(i, end - i);
    out += to_lower(piece) == word ? instead : piece;
    i = end;
  }
  return out;
}

}  // namespace

std::optional<std::string> TaskLearningAgent::Session::other_name_of_thing(const std::string& text,
                                                                           const language::Reply& reply,
                                                                           const language::ReplyContext& context) const {
  if (context.asked != language::Asked::kGoal || !context.object || !std::holds_alternative<language::Unusable>(reply))
    return std::nullopt;
  auto rule = language::read_rule(world(), agent_.understanding_.lexicon(), text, context.object);
  if (!rule || rule->clauses.size() != 1) return std::nullopt;
  const language::RuleClause& clause = rule->clauses.front();
  if (clause.thing || clause.places.empty() || clause.classes.size() != 1) return std::nullopt;
  // One word, in the singular, that names nothing here: a class is said in
  // the plural ("toys go in the basket"), the thing asked about in the
  // singular.
  const language::RuleClass& said = clause.classes.front();
  if (said.rest || said.phrase.empty() || said.phrase != said.head || !said.modifiers.empty() ||
      is_general_head(said.head))
    return std::nullopt;
  if (language::singular_forms(said.phrase).size() != 1) return std::nullopt;
  if (agent_.understanding_.category(world(), said.phrase).has_value()) return std::nullopt;
  return said.phrase;
}

TaskLearningAgent::Session::Flow<std::optional<language::Reply>> TaskLearningAgent::Session::ask_other_name(
    const std::string& word, const std::string& text, const Question& asked, const language::ReplyContext& context) {
  const ObjectId object = *context.object;
  Question q = question(QuestionKind::kConfirmGoal, language::ask_other_name(word, world(), object), asked.object);
  auto heard = converse(q, this->context(language::Asked::kYesNo, object),
                        [](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::YesNo>(r)) return std::nullopt;
                          return language::asked_yes_or_no();
                        });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply || !std::get<language::YesNo>(*heard->reply).yes) return std::optional<language::Reply>();
  const std::string again = with_word_replaced(text, word, language::spoken_category(world(), object));
  return std::optional<language::Reply>(agent_.understanding_.reply(world(), context, again));
}

std::optional<language::RuleReading> TaskLearningAgent::Session::rule_in_reply(
    const std::string& text, const language::Reply& reply, const language::ReplyContext& context) const {
  // The thing asked about called by another word is not a class.
  if (other_name_of_thing(text, reply, context)) return std::nullopt;
  // "there": the place named last, or the place a proposal asked about
  // ("yep. hats and caps go there too").
  std::optional<ObjectId> there = context.recent_place;
  if (context.proposal && context.object)
    if (const std::vector<ObjectId> proposed = destinations(world(), *context.proposal, *context.object);
        !proposed.empty())
      there = proposed.front();
  auto rule = language::read_rule(world(), agent_.understanding_.lexicon(), text, context.object, there);
  if (!rule || !rule->has_class_clause()) return std::nullopt;
  const auto* unusable = std::get_if<language::Unusable>(&reply);
  const bool understood = unusable == nullptr;
  // A class that is only the world's kinds named in the plural ("plates and
  // forks go in the dishwasher") is the reply's ordinary reading, where it
  // has one; where it has none ("pots go on the right shelf", said when
  // asked for a part of the task), it says where every such thing goes. So
  // is "an object" ("Repeat the following tasks while an object is on the
  // table").
  // A word that the reference resolves to one kind only through WordNet
  // ("clothes" to the dress: not a word of its name) is a class all the
  // same; "plates" for the plate is that kind.
  auto a_class_of_its_own = [&](const language::RuleClass& c) {
    if (c.rest) return true;
    if (c.phrase.empty() || (is_general_head(c.head) && c.modifiers.empty())) return false;
    if (is_general_head(c.head)) return true;
    const std::optional<std::string> kind = agent_.understanding_.category(world(), c.phrase);
    if (!kind || (!understood && c.phrase != c.head)) return true;
    std::string name = *kind;
    std::replace(name.begin(), name.end(), '-', ' ');
    const std::vector<std::string> words = split_words(name);
    return std::find(words.begin(), words.end(), c.head) == words.end();
  };
  std::size_t class_clauses = 0;
  bool rest = false;
  for (const language::RuleClause& clause : rule->clauses) {
    if (clause.thing) continue;
    if (std::any_of(clause.classes.begin(), clause.classes.end(), a_class_of_its_own)) ++class_clauses;
    rest = rest || std::any_of(clause.classes.begin(), clause.classes.end(), [](const auto& c) { return c.rest; });
  }
  if (class_clauses == 0) return std::nullopt;
  // What the reply's own reading takes ("tools go in the top drawer": each
  // tool's goal) is left to it, unless the rule says more than one clause or
  // "other".
  // An unusable reply that asks what to do with the things at a place
  // ("start with the stuff on the floor": "What should I do with the things
  // on the floor?") is understood as far as it goes: a step, not a rule.
  if (unusable != nullptr && !unusable->topic_places.empty()) return std::nullopt;
  // (A yes or a no whose rest is no goal of the thing asked about takes no
  // class: "yep. hats go there too" is a rule; "no, shoes go in the
  // wardrobe", asked about the sneaker, is the sneaker's goal.)
  const auto* yes_no = std::get_if<language::YesNo>(&reply);
  const bool rest_answers =
      yes_no == nullptr || (context.object && agent_.understanding_.goal_in_rest(world(), context, *yes_no));
  if (understood && class_clauses < 2 && !rest && rest_answers) return std::nullopt;
  return rule;
}

GoalScope TaskLearningAgent::Session::said_scope() const {
  GoalScope scope;
  scope.task = progress_.task.name;
  if (progress_.current) {
    scope.subtask = current().verb;
    scope.place = world().universe->info(current().places.front()).category;
  }
  return scope;
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::hear_rule(language::RuleReading rule,
                                                                      const std::string& text) {
  sources_.hear(text);
  // A lesson of its own: "undo" takes the rule back.
  begin_lesson(text);
  for (language::RuleClause& clause : rule.clauses)
    if (auto chosen = which_place_of(clause); !chosen) return tl::unexpected(chosen.error());
    else if (*chosen) clause.places = {**chosen};
  for (ClassRule& said : class_rules_of(world(), rule, RuleSource::kPerson, text, said_scope(), kPersonRuleConfidence))
    if (auto kept = store_class_rule(said); !kept) spdlog::warn("{}", kept.error().message);
  say(language::read_back_rule(world(), rule));
  if (!rule.not_understood.empty()) say(language::rule_parts_not_followed(rule.not_understood));
  spdlog::info("a person's rule: {}", language::read_back_rule(world(), rule));
  return {};
}

TaskLearningAgent::Session::Flow<std::optional<ObjectId>> TaskLearningAgent::Session::which_place_of(
    const language::RuleClause& clause) {
  const std::optional<std::string> which = language::ask_which_place_of(world(), clause);
  if (!which || !person()) return std::optional<ObjectId>();
  Question q = question(QuestionKind::kWhich, *which);
  q.choices = clause.places;
  language::ReplyContext context = this->context(language::Asked::kWhich);
  context.choices = clause.places;
  auto heard = converse(q, context, chosen_among(clause.places));
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) return std::optional<ObjectId>();
  return std::optional<ObjectId>(std::get<language::Chosen>(*heard->reply).object);
}

Status TaskLearningAgent::Session::store_class_rule(const ClassRule& rule) {
  sources_.add_rule(rule);
  return lessons_.learn_class_rule(agent_.knowledge_, rule);
}

Status TaskLearningAgent::Session::keep_induced_rules_learned() {
  // Without a store there is nothing to keep: the rules are induced anew
  // from the goals whenever they are asked for.
  if (!learning_ || !agent_.store_) return {};
  return keep_induced_rules(agent_.knowledge_, agent_.store_, sources_.concepts());
}

}  // namespace apprentice
