// Internal to the agent: what "forget X" forgets, decided from what is
// known, without a session, a teacher or a store. The session carries the
// decision out (agent_dialogue.cc): the goals in a lesson of their own, so
// that "undo" right after brings them back; a person's rule for good.
//
// The words name, in this order of preference:
//   - a kind of thing here (`category`, the reader's), unless a rule is
//     named by the same words and the kind is no learned kind's own name
//     ("forget paper": the rule about paper things, not the newspaper that
//     WordNet calls paper);
//   - a kind known but not here, by its name, plural or last word
//     (kinds_known_by, agent/teacher_questions.h); several: which one;
//   - a person's or an induced rule in use (rules_named,
//     agent/class_rule_knowledge.h); several said differently: which one.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "knowledge/goal_memory.h"
#include "knowledge/preferences.h"

namespace apprentice {

struct ForgetDecision {
  enum class Kind {
    kGoals,      // forget `goals`, the goals of `category`
    kRules,      // forget `rules` for good, all said alike
    kWhichKind,  // several kinds fit the words: asked which (nothing forgotten)
    kWhichRule,  // several rules fit the words: asked which (nothing forgotten)
    kNothing,    // nothing known by the words
  } kind = Kind::kNothing;
  std::string category;
  std::vector<GoalKey> goals;
  std::vector<ClassRule> rules;
  // What to tell the teacher once it is done, in plain English.
  std::string reply;
};

// `what` is the teacher's words after "forget"; `category` the kind of
// thing here they name, when the reader found one.
ForgetDecision decide_forget(const std::string& what, std::optional<std::string> category, const GoalMemory& goals,
                             std::span<const ClassRule> rules_in_use);

}  // namespace apprentice
