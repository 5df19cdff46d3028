// The benchmark's simulated teacher: the experiments' simulated instructor
// (instructor/simulated_instructor.h), who teaches the task structure and
// answers from the scenario's intent, with two things a TidyBot protocol
// needs:
//  - the person's rule (the annotator's note) said once, in the person's
//    own words, at a chosen question: before the task (the first question
//    about the task's steps) or at the first question about where a thing
//    goes;
//  - answering, or not, questions about where things go: a teacher that
//    does not (the agent working alone) says "skip it", so that the thing
//    stays where it is.
// It counts the questions the agent asks about things (where one goes,
// yes or no to a proposal, which place it means).
#pragma once

#include <optional>
#include <string>

#include "instructor/simulated_instructor.h"

namespace apprentice::benchmark {

enum class NoteAt { kNever, kTaskStep, kGoalQuestion };

struct TeacherOptions {
  std::string note;                // the person's rule, said once
  NoteAt note_at = NoteAt::kNever;
  bool answers_about_things = true;  // false: "skip it" to every question about a thing
};

class BenchmarkTeacher final : public Instructor {
 public:
  BenchmarkTeacher(Scenario scenario, TeacherOptions options);

  Result<std::string> answer(const Question& question, const World& world) override;

  // Questions about things: where one goes, a yes/no about one, which place.
  int questions_about_things() const { return questions_; }
  bool note_given() const { return note_given_; }

 private:
  SimulatedInstructor simulated_;
  TeacherOptions options_;
  bool note_given_ = false;
  int questions_ = 0;
};

}  // namespace apprentice::benchmark
