// Logical forms of the restricted English the agent understands: the
// instructor's task structure, goal descriptions, action commands and yes/no
// answers (see docs/language.md for the grammar). A logical form says what
// the words say and nothing about the world: noun phrases stay words until
// language/grounding.h maps them onto objects.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace apprentice::language {

// A noun phrase as written, lower-cased: "the recycling bin" has article
// "the" and words {"recycling", "bin"}; "plastic-bottle" keeps its hyphen.
struct NounPhrase {
  std::string article;             // "", "the", "a" or "an"
  std::vector<std::string> words;  // never empty

  // The words joined by spaces: "recycling bin", "plastic-bottle".
  std::string text() const;
  // "the object" / "object": the object of interest.
  bool is_object_of_interest() const;

  friend bool operator==(const NounPhrase&, const NounPhrase&) = default;
};

// The two spatial relations of the kitchen: "in" (also "into", "inside") and "on".
enum class Relation { kIn, kOn };

// "X is in Y" / "X is on Y".
struct Placement {
  NounPhrase thing;
  Relation relation = Relation::kIn;
  NounPhrase place;
  friend bool operator==(const Placement&, const Placement&) = default;
};

// "Y is closed", "Y is open", or a property the agent has no predicate for
// ("the dishwasher is turned on", "the sink is full of water").
enum class Property { kClosed, kOpen, kUnknown };

struct PropertyStatement {
  NounPhrase thing;
  Property property = Property::kClosed;
  std::vector<std::string> words;  // the predicate's words: {"turned", "on"}
  friend bool operator==(const PropertyStatement&, const PropertyStatement&) = default;
};

using Conjunct = std::variant<Placement, PropertyStatement>;

// "If the object is a ketchup then the goal is that ..." (category set) or
// the LLM's "the goal is that ..." (no category).
struct GoalDescription {
  std::optional<NounPhrase> category;
  std::vector<Conjunct> conjuncts;  // never empty
  friend bool operator==(const GoalDescription&, const GoalDescription&) = default;
};

// An imperative whose verb is not a known action: the name of a task to
// learn ("Tidy kitchen."), as in the paper's agent.
struct TaskName {
  std::vector<std::string> words;  // {"tidy", "kitchen"}
  friend bool operator==(const TaskName&, const TaskName&) = default;
};

// "Repeat the following tasks while an object is on the table."
struct RepeatWhile {
  Relation relation = Relation::kOn;
  NounPhrase place;
  friend bool operator==(const RepeatWhile&, const RepeatWhile&) = default;
};

// "Clear an object that is on the table."
struct SubtaskCommand {
  std::string verb;  // "clear"
  Relation relation = Relation::kOn;
  NounPhrase place;
  friend bool operator==(const SubtaskCommand&, const SubtaskCommand&) = default;
};

// "You are done."
struct Done {
  friend bool operator==(const Done&, const Done&) = default;
};

// "Repeat."
struct Repeat {
  friend bool operator==(const Repeat&, const Repeat&) = default;
};

// The primitive actions of the kitchen, by the verbs that name them.
enum class ActionVerb { kOpen, kClose, kPickUp, kPut };

// Where an action's second noun phrase stands: "from the table" (pick up),
// "in the fridge" / "on the counter" (put).
enum class ActionPreposition { kFrom, kIn, kOn };

// "Open the fridge.", "Pick up ceramic-plate from table", "Put plastic
// bottle in recycling bin".
struct ActionCommand {
  ActionVerb verb = ActionVerb::kOpen;
  NounPhrase object;
  std::optional<ActionPreposition> preposition;  // set iff destination is
  std::optional<NounPhrase> destination;
  friend bool operator==(const ActionCommand&, const ActionCommand&) = default;
};

// "yes" / "no", in any case, with or without a period.
struct Answer {
  bool yes = false;
  friend bool operator==(const Answer&, const Answer&) = default;
};

using LogicalForm = std::variant<TaskName, RepeatWhile, SubtaskCommand, Done, Repeat,
                                 GoalDescription, ActionCommand, Answer>;

std::string_view to_string(Relation relation);
std::string_view to_string(ActionVerb verb);
std::string_view to_string(ActionPreposition preposition);

// A stable s-expression for golden files and logs, for example
//   (goal (category "ceramic-plate") (in "object" "dishwasher") (closed "dishwasher"))
//   (action put "plastic bottle" (in "recycling bin"))
//   (subtask "clear" (on "table"))
// Articles are dropped: they never change what a phrase refers to here.
std::string format_logical_form(const LogicalForm& form);
std::string format_conjunct(const Conjunct& conjunct);

}  // namespace apprentice::language
