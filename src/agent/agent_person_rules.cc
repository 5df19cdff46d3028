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
  // ("neither": the clause keeps every place it fits.)
  const auto* chosen = heard->reply ? std::get_if<language::Chosen>(&*heard->reply) : nullptr;
  if (chosen == nullptr) return std::optional<ObjectId>();
  return std::optional<ObjectId>(chosen->object);
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
