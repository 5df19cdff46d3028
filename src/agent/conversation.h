// Internal to the agent: the line to the teacher in one session. It owns
// what was said ahead of its question:
//   - the answer said after an undo in the same reply ("oops scratch that,
//     the wrench goes in the bottom drawer"), or the rest of a "no", taken
//     as the reply to the next question;
//   - the further steps of a reply about the task's steps ("clear the
//     counter, then the table"), each the reply to the next question about
//     the task's steps;
//   - the place named last, which "the door" means.
// It reads nothing (the session reads each reply, language/reply.h) and
// changes no knowledge. Without a dialogue (performing alone) it says
// nothing and has no replies.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "instructor/dialogue.h"
#include "util/result.h"
#include "world/world.h"

namespace apprentice {

class Conversation {
 public:
  // `dialogue` may be null; it must outlive the conversation.
  explicit Conversation(Dialogue* dialogue) : dialogue_(dialogue) {}

  bool with_teacher() const { return dialogue_ != nullptr; }
  // Whether the teacher is a person (not a program).
  bool with_person() const { return dialogue_ != nullptr && dialogue_->instructor_is_person(); }
  // The replies counted as instructions so far; zero without a teacher.
  int instructions() const { return dialogue_ ? dialogue_->counts().instructions : 0; }

  void say(const std::string& statement, Voice voice = Voice::kNarration) {
    if (dialogue_) dialogue_->say(statement, voice);
  }
  // The teacher sees `action`, done, with the world after it.
  void observe(const Action& action, const World& world) {
    if (dialogue_) dialogue_->observe(action, world);
  }

  // A reply to a question: its text, and whether it was a step said ahead
  // in an earlier reply (then it is no new instruction).
  struct Said {
    std::string text;
    bool said_ahead = false;
  };
  // The next reply to `asked`: an answer said ahead, else, at a question
  // about the task's steps (`about_steps`), a step said ahead, else the
  // teacher's. Requires a teacher. An error when the teacher left.
  Result<Said> next_reply(const Question& asked, const World& world, bool about_steps);
  // Counts `text`, the reply to `asked`, as an instruction.
  void count(const Question& asked, const std::string& text) {
    if (dialogue_) dialogue_->count_reply(asked, text);
  }
  // `text` answers the next question, whatever it is.
  void answer_ahead(std::string text) { answers_ahead_.push_back(std::move(text)); }
  // `steps` answer the next questions about the task's steps, in order.
  void steps_ahead(const std::vector<std::string>& steps) { steps_ahead_.insert(steps_ahead_.end(), steps.begin(), steps.end()); }
  // An undo: the steps said ahead were said of what is undone.
  void drop_steps_ahead() { steps_ahead_.clear(); }

  // The place named last: what "the door" means.
  void named_place(ObjectId place) { recent_place_ = place; }
  std::optional<ObjectId> recent_place() const { return recent_place_; }

 private:
  Dialogue* dialogue_;
  std::deque<std::string> answers_ahead_;
  std::deque<std::string> steps_ahead_;
  std::optional<ObjectId> recent_place_;
};

}  // namespace apprentice
