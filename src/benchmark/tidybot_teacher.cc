#include "benchmark/tidybot_teacher.h"

namespace apprentice::benchmark {

BenchmarkTeacher::BenchmarkTeacher(Scenario scenario, TeacherOptions options)
    : simulated_(std::move(scenario)), options_(std::move(options)) {}

Result<std::string> BenchmarkTeacher::answer(const Question& question, const World& world) {
  const bool about_a_thing = question.object.has_value() &&
                             (question.kind == QuestionKind::kSubtaskStep || question.kind == QuestionKind::kConfirmGoal ||
                              question.kind == QuestionKind::kWhich || question.kind == QuestionKind::kNextAction);
  if (about_a_thing) ++questions_;
  if (!note_given_ && !options_.note.empty()) {
    const bool now = (options_.note_at == NoteAt::kTaskStep && question.kind == QuestionKind::kTaskStep) ||
                     (options_.note_at == NoteAt::kGoalQuestion && question.kind == QuestionKind::kSubtaskStep &&
                      question.object.has_value());
    if (now) {
      note_given_ = true;
      return options_.note;
    }
  }
  if (about_a_thing && !options_.answers_about_things) return std::string("skip it");
  return simulated_.answer(question, world);
}

}  // namespace apprentice::benchmark
