// The instructor, as the agent sees it: someone who answers the agent's
// questions in English. A person at the terminal and the simulated
// instructor of the experiments implement the same interface.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "util/result.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace apprentice {

enum class QuestionKind {
  kTaskName,       // "What task should I learn?"
  kTaskStep,       // "What is the next goal or subtask of tidy?"
  kSubtaskStep,    // "What is the next goal or subtask of clear?" (about `object`, or,
                   // without one, about the subtask: is there more to it?)
  kNextAction,     // "What do I do next for clear?" (towards `goal`)
  kConfirmGoal,    // "[LM] For a ceramic-plate on the table is the goal that ...?"
  kConfirmAction,  // "[LM] For the ceramic-plate should I 'Pick up ceramic-plate'?"
};

const char* to_string(QuestionKind kind);
inline bool is_yes_no(QuestionKind kind) {
  return kind == QuestionKind::kConfirmGoal || kind == QuestionKind::kConfirmAction;
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
  // Something the agent says that needs no reply ("I cannot do that: ...").
  virtual void hear(std::string_view statement) { (void)statement; }
};

}  // namespace apprentice
