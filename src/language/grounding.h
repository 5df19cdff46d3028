// Grounding: from a logical form to what it means in the current world — a
// goal (facts over object ids), an action, a step of the task structure —
// or a typed failure with a reason the agent can say.
//
// Noun phrases map to perceived objects by category, hyphenated or spaced
// ("plastic bottle" is plastic-bottle); "the object" is the object of
// interest. Words the world does not use go to WordNet (language/lexicon.h),
// and a WordNet mapping is taken only if exactly one object of the current
// world fits: the grounder would rather fail than ground to the wrong thing.
// docs/language.md gives the full policy and the failure kinds.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/grounding_types.h"
#include "language/lexicon.h"
#include "language/logical_form.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice::language {

// A step of the task structure, grounded.
struct TaskStep {
  enum class Kind { kTaskName, kRepeatWhile, kSubtask, kDone, kRepeat, kAnswer };
  Kind kind = Kind::kTaskName;
  std::string name;               // the task name ("tidy kitchen") or subtask verb ("clear")
  Relation relation = Relation::kOn;
  std::optional<ObjectId> place;  // RepeatWhile and Subtask: the first of `places`
  bool yes = false;               // Answer
  // RepeatWhile and Subtask: every place meant, in id order. Several when
  // the phrase names a kind of place of which there are several here ("an
  // object that is in a bag" with three bags).
  std::vector<ObjectId> places = {};
};

using Grounding = std::variant<Goal, Action, TaskStep, GroundingFailure>;

struct Interpretation {
  std::optional<LogicalForm> form;  // absent iff the sentence did not parse
  Grounding result;
  std::vector<Reference> references;  // in the order the phrases were grounded
  std::optional<ObjectId> bound_object;  // what "the object" / the described object meant

  bool ok() const { return !std::holds_alternative<GroundingFailure>(result); }
  const GroundingFailure* failure() const { return std::get_if<GroundingFailure>(&result); }
};

class Grounder {
 public:
  explicit Grounder(Lexicon lexicon) : lexicon_(std::move(lexicon)) {}

  const Lexicon& lexicon() const { return lexicon_; }

  // Grounds a logical form in `world`. `object_of_interest` is what "the
  // object" means; for "If the object is a X then ..." it must be an X
  // (without one, the first X of the world in id order stands for it).
  Interpretation ground(const LogicalForm& form, const World& world,
                        std::optional<ObjectId> object_of_interest) const;

  // parse() then ground(); a sentence that does not parse is an
  // `uninterpretable` failure whose detail is the parser's message.
  Interpretation interpret(std::string_view sentence, const World& world,
                           std::optional<ObjectId> object_of_interest) const;

  // The same, for callers that expect one kind of answer: anything else
  // (a task name where an action was expected, say) becomes a failure —
  // an unknown verb is an `unknown-word`.
  Interpretation interpret_goal(std::string_view sentence, const World& world,
                                std::optional<ObjectId> object_of_interest) const;
  Interpretation interpret_action(std::string_view sentence, const World& world,
                                  std::optional<ObjectId> object_of_interest) const;

 private:
  Lexicon lexicon_;
};

// One line for golden files and `apprentice interpret`:
//   "goal (and (in ketchup1 fridge1) (closed fridge1))"
//   "action (open fridge1)"
//   "task tidy kitchen" | "repeat-while on table1" | "subtask clear on table1"
//   "done" | "repeat" | "answer yes"
//   "failure affordance-mismatch closed recycling-bin1"
std::string format_grounding(const World& world, const Grounding& grounding);

}  // namespace apprentice::language
