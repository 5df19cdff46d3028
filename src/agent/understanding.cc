#include "agent/understanding.h"

#include <algorithm>

#include "language/grounding.h"
#include "language/parser.h"
#include "language/reference.h"
#include "language/rule_in_reply.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice {

struct Understanding::Impl {
  language::Grounder grounder{language::Lexicon::open_default()};
  bool vectors_looked_for = false;
  std::optional<vectors::WordVectors> vectors;
};

Understanding::Understanding() : impl_(std::make_unique<Impl>()) {}
Understanding::Understanding(Understanding&&) noexcept = default;
Understanding& Understanding::operator=(Understanding&&) noexcept = default;
Understanding::~Understanding() = default;

Result<language::LogicalForm> Understanding::parse(std::string_view sentence) const {
  return language::parse(sentence);
}

std::string_view to_string(MeaningFailure failure) {
  switch (failure) {
    case MeaningFailure::kNone: return "";
    case MeaningFailure::kUnknownWord: return language::to_string(language::FailureKind::kUnknownWord);
    case MeaningFailure::kUninterpretable: return language::to_string(language::FailureKind::kUninterpretable);
    case MeaningFailure::kUngroundedObject: return language::to_string(language::FailureKind::kUngroundedObject);
    case MeaningFailure::kAffordanceMismatch: return language::to_string(language::FailureKind::kAffordanceMismatch);
    case MeaningFailure::kUnknownPredicate: return language::to_string(language::FailureKind::kUnknownPredicate);
    case MeaningFailure::kNoDestination: return "no-destination";
    case MeaningFailure::kAlreadyHolds: return "already-holds";
    case MeaningFailure::kUnreachable: return "unreachable";
  }
  return "";
}

MeaningFailure meaning_failure(language::FailureKind kind) {
  switch (kind) {
    case language::FailureKind::kUnknownWord: return MeaningFailure::kUnknownWord;
    case language::FailureKind::kUninterpretable: return MeaningFailure::kUninterpretable;
    case language::FailureKind::kUngroundedObject: return MeaningFailure::kUngroundedObject;
    case language::FailureKind::kAffordanceMismatch: return MeaningFailure::kAffordanceMismatch;
    case language::FailureKind::kUnknownPredicate: return MeaningFailure::kUnknownPredicate;
  }
  return MeaningFailure::kUninterpretable;
}

namespace {

GoalMeaning goal_meaning(const language::Interpretation& interpretation) {
  GoalMeaning meaning;
  if (const Goal* goal = std::get_if<Goal>(&interpretation.result)) {
    meaning.goal = *goal;
  } else if (const auto* failure = interpretation.failure()) {
    meaning.failure_kind = meaning_failure(failure->kind);
    meaning.failure = failure->message;
  } else {
    meaning.failure_kind = MeaningFailure::kUninterpretable;
    meaning.failure = "That is not a goal.";
  }
  return meaning;
}

ActionMeaning action_meaning(const language::Interpretation& interpretation) {
  ActionMeaning meaning;
  if (const Action* action = std::get_if<Action>(&interpretation.result)) {
    meaning.action = *action;
  } else if (const auto* failure = interpretation.failure()) {
    meaning.failure_kind = meaning_failure(failure->kind);
    meaning.failure = failure->message;
  } else {
    meaning.failure_kind = MeaningFailure::kUninterpretable;
    meaning.failure = "That is not an action.";
  }
  return meaning;
}

}  // namespace

GoalMeaning Understanding::goal(const World& world, std::string_view sentence, ObjectId object) {
  return goal_meaning(impl_->grounder.interpret_goal(sentence, world, object));
}

GoalMeaning Understanding::goal(const World& world, const language::GoalDescription& form, ObjectId object) {
  return goal_meaning(impl_->grounder.ground(language::LogicalForm(form), world, object));
}

ActionMeaning Understanding::action(const World& world, std::string_view sentence, std::optional<ObjectId> object) {
  return action_meaning(impl_->grounder.interpret_action(sentence, world, object));
}

ActionMeaning Understanding::action(const World& world, const language::ActionCommand& form,
                                    std::optional<ObjectId> object) {
  return action_meaning(impl_->grounder.ground(language::LogicalForm(form), world, object));
}

std::optional<ObjectId> Understanding::place(const World& world, const language::NounPhrase& phrase,
                                             language::Relation relation) {
  language::RepeatWhile probe{relation, phrase};
  auto interpretation = impl_->grounder.ground(language::LogicalForm(probe), world, std::nullopt);
  if (const auto* step = std::get_if<language::TaskStep>(&interpretation.result)) return step->place;
  return std::nullopt;
}

language::Reply Understanding::reply(const World& world, const language::ReplyContext& context,
                                     std::string_view text) const {
  return language::read_reply(impl_->grounder, world, context, text);
}

language::ReplyActs Understanding::acts(const World& world, const language::ReplyContext& context,
                                        std::string_view text) const {
  return language::read_acts(impl_->grounder, world, context, text);
}

std::optional<language::GoalGiven> Understanding::goal_in_rest(const World& world, const language::ReplyContext& context,
                                                             const language::YesNo& answer) const {
  return language::goal_in_rest(impl_->grounder, world, context, answer);
}

std::vector<std::string> Understanding::example_replies(const World& world,
                                                        const language::ReplyContext& context) const {
  return language::example_replies(world, context);
}

std::optional<std::string> Understanding::category(const World& world, std::string_view phrase) const {
  return language::category_named(impl_->grounder.lexicon(), world, phrase);
}

std::optional<language::RuleReading> Understanding::rule_in_reply(const World& world, std::string_view text,
                                                                  const language::Reply& reply,
                                                                  const language::ReplyContext& context) const {
  return language::rule_in_reply(impl_->grounder, world, text, reply, context);
}

std::optional<std::string> Understanding::other_name_of_asked(const World& world, std::string_view text,
                                                              const language::Reply& reply,
                                                              const language::ReplyContext& context) const {
  return language::other_name_of_asked(impl_->grounder, world, text, reply, context);
}

std::vector<ObjectId> Understanding::may_name(const World& world, std::string_view phrase) const {
  language::NounPhrase noun{"", split_words(to_lower(phrase))};
  while (!noun.words.empty() && language::is_determiner(noun.words.front()))
    noun.words.erase(noun.words.begin());
  if (noun.words.empty()) return {};
  language::ReferenceContext context{world, impl_->grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  auto found = language::candidates_for(noun, language::Role::kItem, context);
  const auto* set = std::get_if<language::CandidateSet>(&found);
  return set == nullptr ? std::vector<ObjectId>() : set->objects;
}

std::vector<std::string> Understanding::kinds_under(const World& world, std::string_view phrase) const {
  std::vector<std::string> kinds;
  for (ObjectId o : world.universe->of_kind(ObjectKind::kItem)) {
    const std::string& kind = world.universe->info(o).category;
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  }
  return impl_->grounder.lexicon().kinds_under(phrase, kinds);
}

const language::Lexicon& Understanding::lexicon() const { return impl_->grounder.lexicon(); }

const vectors::WordVectors* Understanding::vectors() const {
  if (!impl_->vectors_looked_for) {
    impl_->vectors_looked_for = true;
    impl_->vectors = vectors::open_default_vectors();
  }
  return impl_->vectors ? &*impl_->vectors : nullptr;
}

bool Understanding::is_known_action_word(std::string_view word) const {
  std::string w = to_lower(trim(word));
  return w == "open" || w == "close" || w == "pick" || w == "put";
}

}  // namespace apprentice
