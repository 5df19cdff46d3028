// A person's preferences about classes of things: "fruit goes on the
// coffee table", "plastic things in the left box", "other clothes on the
// chair". A rule comes from the examples the agent was taught (induced:
// knowledge/induction.h), from the person's own sentence, from an LLM's
// summary of what was taught, or later from a fleet; it is stored with its
// evidence (knowledge/store.h) and proposes a destination for every later
// thing it covers, in any world that has the place (knowledge/decision.h).
//
// Nothing here knows WordNet or word vectors: which things a class covers
// is asked of a ConceptSource the agent supplies (knowledge/concepts.h).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "knowledge/goal_memory.h"

namespace apprentice {

// Where a thing goes, as a goal template without the thing: the relation to
// one place, and what else the goal says of that place.
//   "on the coffee table":                  {"on", coffee-table, {}}
//   "in the fridge, and the fridge closed": {"in", fridge, {(closed fridge)}}
struct Destination {
  std::string relation;  // the placing predicate: "in" or "on"
  // By category, with the properties that tell it apart where the world has
  // several ("shelf" [left]), as in goal templates.
  GoalTemplateArgument place;
  // Literals about the place alone ("the fridge ends closed").
  std::vector<GoalTemplateLiteral> doors;
  friend bool operator==(const Destination&, const Destination&) = default;
};

// The destination a goal template gives: exactly one in/on literal with the
// object of interest first and a place second, and otherwise only literals
// whose arguments are all that place. nullopt for any other goal ("(in ?o
// sink) (not (dirty ?o))" is not a placement only).
std::optional<Destination> destination_of(std::span<const GoalTemplateLiteral> literals);
// The goal template of a destination: (relation ?o place), then the doors.
std::vector<GoalTemplateLiteral> destination_literals(const Destination& destination);
// "on the coffee-table", "in the [left storage-box]", "in the fridge (closed
// fridge)": for logs, the store's keys and tests. The agent's English is in
// language/narration.h.
std::string format_destination(const Destination& destination);

// Where a preference was learned: the task, the subtask and the kind of
// place the things were at ("tidy kitchen", "clear", "table"). An empty
// field matches anything (a person's rule said before any task).
struct GoalScope {
  std::string task;
  std::string subtask;
  std::string place;
  friend bool operator==(const GoalScope&, const GoalScope&) = default;
};

// Where a rule came from.
enum class RuleSource {
  kInduced,  // from the examples taught (knowledge/induction.h)
  kPerson,   // from the person's own sentence ("Put toys in the storage box")
  kLlm,      // from an LLM's summary of the examples, read as a person's rule is
  kFleet,    // from other robots' knowledge (issue 23)
};
// "induced", "person", "llm", "fleet": for the store and logs.
std::string_view rule_source_name(RuleSource source);
std::optional<RuleSource> rule_source_from_name(std::string_view name);

// A preference about a class of things.
struct ClassRule {
  // The class: a WordNet lemma ("edible fruit") or the person's word
  // ("toys", "electronics"); "" when the rule is about modifiers alone
  // ("plastic things") or is "the rest" alone.
  std::string class_name;
  // The ConceptSource's identity of the class ("wordnet:07705931"), when it
  // has one: an induced class is exactly that synset, not every sense of
  // the word. "" for a person's word.
  std::string class_id;
  // Words every thing the rule covers has in its name ("plastic",
  // "stainless steel", "dirty"), in the order said.
  std::vector<std::string> modifiers;
  // Only the things of the class no other rule of the scope takes: "other
  // clothes", "everything else".
  bool rest = false;
  Destination destination;
  // Kinds of thing the class covers that do not go there (a teacher's "no",
  // or examples taught otherwise), in the order learned.
  std::vector<std::string> exceptions;
  RuleSource source = RuleSource::kInduced;
  // The sentence it was read from (a person's, an LLM's); "" when induced.
  std::string said;
  // The kinds it was induced from or confirmed on: "banana", "apple".
  std::vector<std::string> evidence;
  // How sure its source is that the rule holds, 0..1: for an induced rule
  // the share of belief the examples give this class among the classes
  // that cover them (the size principle, knowledge/induction.h).
  double confidence = 0;
  GoalScope scope;
  friend bool operator==(const ClassRule&, const ClassRule&) = default;
};

// What identifies a rule in the store and for `forget`: its scope, source,
// class, modifiers, rest and destination (not its evidence, exceptions or
// confidence, which change as it is confirmed). One line.
std::string class_rule_key(const ClassRule& rule);

// "edible fruit -> on the coffee-table (induced from banana, apple; 0.83)":
// one line for logs and tests. The English of `apprentice knowledge` is the
// agent's (agent/explanation.h).
std::string format_class_rule(const ClassRule& rule);

// The class rules the agent holds, in the order learned.
class ClassRules {
 public:
  // Replaces a rule with the same key (class_rule_key), else appends.
  void add(ClassRule rule);
  // Removes the rule with that key; whether there was one.
  bool remove(const ClassRule& rule);
  // The rule with that key, or null.
  const ClassRule* find(const ClassRule& rule) const;
  ClassRule* find(const ClassRule& rule);
  const std::vector<ClassRule>& all() const { return rules_; }
  std::size_t size() const { return rules_.size(); }
  bool empty() const { return rules_.empty(); }

 private:
  std::vector<ClassRule> rules_;
};

}  // namespace apprentice
