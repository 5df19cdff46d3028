// The instructor, as the agent sees it: someone who answers the agent's
// questions in English. A person at the terminal, the simulated instructor
// of the experiments and a program's callback implement the same
// interface; a question's `text` is all a person or a callback needs.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

enum class QuestionKind {
  kTaskName,       // "What task should I learn?"
  kTaskStep,       // "What should I do next to tidy the kitchen?"
  kSubtaskStep,    // about `object`: "Where should the ketchup on the table go?" (its goal);
                   // without one, about the subtask: "Is there more to clear on the table,
                   // or is that all?"
  kNextAction,     // "What should I do next so that ...?" (towards `goal`)
  kConfirmGoal,    // "[LM] For a ceramic plate on the table, is the goal that ...?"
  kConfirmAction,  // "[LM] For the ceramic plate, should I 'Pick up ceramic plate'?"
  kWhich,          // "Which drawer: the top drawer or the bottom drawer?" (one of `choices`)
  kConfirm,        // another yes/no, about `object`: "There are still 2 things on the table: ... Shall I leave them?"
};

const char* to_string(QuestionKind kind);
inline bool is_yes_no(QuestionKind kind) {
  return kind == QuestionKind::kConfirmGoal || kind == QuestionKind::kConfirmAction || kind == QuestionKind::kConfirm;
}

// A question with what it is about, so that an instructor program can
// answer from meaning; a person reads `text`.
struct Question {
  QuestionKind kind = QuestionKind::kTaskName;
  std::string text;
  std::string task;     // "tidy kitchen", once known
  std::string subtask;  // "clear", once known
  std::optional<ObjectId> object;  // the object of interest
  std::optional<Goal> goal;        // kNextAction: the goal pursued; kConfirmGoal: the one proposed
  std::optional<Action> action;    // kConfirmAction: the action proposed
  std::vector<ObjectId> choices;   // kWhich: the things offered
  // kConfirmGoal: other things still to come that the same "yes" puts where
  // `goal` puts `object` ("and the pear and the grapes too?"); a "yes" is
  // for all of them, a "no" for at least one.
  std::vector<ObjectId> together;
};

// What a statement is to the person hearing it.
enum class Voice {
  kNarration,  // what the agent understood and did: read-backs, reports (`teach --quiet` hides these)
  kResponse,   // an answer to what the person typed: help, status, why a reply cannot be used
};

// Implement it to teach the agent from your own program: a person, a
// script, another model. The agent lends `question` and `world` for the
// call only; keep copies, not references. Calls come from the thread that
// runs the agent, one at a time. Return errors as values, never throw.
class Instructor {
 public:
  virtual ~Instructor() = default;
  // The instructor's reply to a question about the current `world`.
  // kCancelled when the instructor has gone (end of input): the agent stops
  // and keeps what it learned; any other error stops it too.
  virtual Result<std::string> answer(const Question& question, const World& world) = 0;
  // Something the agent says that needs no reply ("So the ketchup goes in
  // the fridge, and the fridge ends closed."), if the instructor wants to
  // hear statements of that voice.
  virtual void hear(std::string_view statement) { (void)statement; }
  virtual bool wants(Voice voice) const {
    (void)voice;
    return true;
  }
  // Each action the agent has just executed, as it happens (towards a goal,
  // or putting things back for an undo), with the world after it; both are
  // lent for the call. The agent reports its actions in words through
  // hear() afterwards; this is for an instructor that shows the world as it
  // changes (the page of `apprentice serve`). The default ignores it.
  virtual void observe(const Action& action, const World& world) {
    (void)action;
    (void)world;
  }
  // A person is never given up on: however many replies the agent cannot
  // use, it explains and asks again, until the person ends the session. A
  // program (the simulated instructor, a callback) gets a bounded number of
  // attempts per question (AgentOptions::max_retries), so that a program
  // that keeps saying the same unusable thing cannot make the agent loop
  // forever; the agent then reports what it could not learn.
  virtual bool is_person() const { return false; }
};

}  // namespace apprentice
