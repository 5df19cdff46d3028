// The agent's use of the language module: what a sentence from the
// instructor or the LLM means in the current world. It owns the grounder
// (and through it the WordNet lexicon).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "language/grounding_types.h"
#include "language/lexicon.h"
#include "language/logical_form.h"
#include "language/reply.h"
#include "language/rule_reader.h"
#include "util/result.h"
#include "vectors/word_vectors.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

// Why a sentence gave no goal or action that can be used: how grounding
// failed (language::FailureKind), or, for a goal, what its repair found
// after (goal_repair.h).
enum class MeaningFailure {
  kNone,                // a goal or action was found
  kUnknownWord,         // a word neither the world nor WordNet knows
  kUninterpretable,     // the grammar fails, or it is not a goal (an action)
  kUngroundedObject,    // no such thing here, or more than one fits
  kAffordanceMismatch,  // closing a lidless bin
  kUnknownPredicate,    // "turned on": no predicate for it
  kNoDestination,       // without what cannot hold, it says nowhere to put the thing
  kAlreadyHolds,        // the goal holds already
  kUnreachable,         // no way to reach the goal
};

// The name in notes and logs: "", "unknown-word", "uninterpretable",
// "ungrounded-object", "affordance-mismatch", "unknown-predicate",
// "no-destination", "already-holds", "unreachable".
std::string_view to_string(MeaningFailure failure);
MeaningFailure meaning_failure(language::FailureKind kind);

// A goal, or why none: `failure` is a sentence the agent can say.
struct GoalMeaning {
  std::optional<Goal> goal;
  MeaningFailure failure_kind = MeaningFailure::kNone;  // when no goal
  std::string failure;
};

struct ActionMeaning {
  std::optional<Action> action;
  MeaningFailure failure_kind = MeaningFailure::kNone;
  std::string failure;
};

class Understanding {
 public:
  Understanding();
  Understanding(Understanding&&) noexcept;
  Understanding& operator=(Understanding&&) noexcept;
  ~Understanding();

  // What a teacher's reply means as an answer to the question in `context`
  // (language/reply.h).
  language::Reply reply(const World& world, const language::ReplyContext& context, std::string_view text) const;
  // The same reply as the acts it holds, in order (language::read_acts):
  // an undo and the answer after it, one-off actions, the teacher's questions.
  language::ReplyActs acts(const World& world, const language::ReplyContext& context, std::string_view text) const;
  // What the rest of a yes or no at a proposed goal says of the thing's
  // goal (language::goal_in_rest).
  std::optional<language::GoalGiven> goal_in_rest(const World& world, const language::ReplyContext& context,
                                                  const language::YesNo& answer) const;
  // The person's rule a reply states, where its own reading `reply` does
  // not already take it; and, at a goal question, the word a reply calls
  // the thing asked about by (language/rule_in_reply.h).
  std::optional<language::RuleReading> rule_in_reply(const World& world, std::string_view text,
                                                     const language::Reply& reply,
                                                     const language::ReplyContext& context) const;
  std::optional<std::string> other_name_of_asked(const World& world, std::string_view text,
                                                 const language::Reply& reply,
                                                 const language::ReplyContext& context) const;
  // Replies that would work at that question, for help and after a reply
  // that could not be used.
  std::vector<std::string> example_replies(const World& world, const language::ReplyContext& context) const;
  // The kind of object a phrase names ("ketchup", "glass"), for "forget
  // <kind of object>", or nullopt if it names none here.
  std::optional<std::string> category(const World& world, std::string_view phrase) const;
  // The things a phrase may name, by part of their names too ("fork" and
  // "forks": the metal forks and the plastic one); none when it names
  // nothing here. For "same for the fork", which is not asked back about.
  std::vector<ObjectId> may_name(const World& world, std::string_view phrase) const;
  // The kinds of thing here that a phrase names as a class, by WordNet
  // ("tools": hammer, screwdriver, wrench); language::Lexicon::kinds_under.
  std::vector<std::string> kinds_under(const World& world, std::string_view phrase) const;

  // The logical form, or kInvalidInput saying what was expected.
  Result<language::LogicalForm> parse(std::string_view sentence) const;
  // A goal statement (the instructor's or the LLM's) about `object`.
  GoalMeaning goal(const World& world, std::string_view sentence, ObjectId object);
  GoalMeaning goal(const World& world, const language::GoalDescription& form, ObjectId object);
  // An action command ("Pick up the ketchup.", "Open dishwasher").
  ActionMeaning action(const World& world, std::string_view sentence, std::optional<ObjectId> object);
  ActionMeaning action(const World& world, const language::ActionCommand& form, std::optional<ObjectId> object);
  // The place a noun phrase names, if exactly one, where things can be
  // `relation` it (on a surface, in a receptacle).
  std::optional<ObjectId> place(const World& world, const language::NounPhrase& phrase,
                                language::Relation relation);
  // Whether the agent knows `word` as the first word of an action ("Open").
  bool is_known_action_word(std::string_view word) const;
  // The WordNet lexicon the grounder uses (also for transfer across worlds).
  const language::Lexicon& lexicon() const;
  // The word vectors (vectors/word_vectors.h), mapped the first time they
  // are asked for; null when they are not installed (said once per process,
  // in plain English, with the command that installs them).
  const vectors::WordVectors* vectors() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace apprentice
