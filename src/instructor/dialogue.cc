#include "instructor/dialogue.h"

#include "language/reply.h"
#include "util/text.h"

namespace apprentice {

const char* to_string(QuestionKind kind) {
  switch (kind) {
    case QuestionKind::kTaskName: return "task-name";
    case QuestionKind::kTaskStep: return "task-step";
    case QuestionKind::kSubtaskStep: return "subtask-step";
    case QuestionKind::kNextAction: return "next-action";
    case QuestionKind::kConfirmGoal: return "confirm-goal";
    case QuestionKind::kConfirmAction: return "confirm-action";
    case QuestionKind::kWhich: return "which";
    case QuestionKind::kConfirm: return "confirm";
  }
  return "unknown";
}

int count_words(std::string_view utterance) { return static_cast<int>(split_words(utterance).size()); }

std::optional<bool> read_yes_no(std::string_view reply) { return language::yes_or_no(reply); }

Result<std::string> Dialogue::ask(const Question& question, const World& world) {
  auto reply = ask_uncounted(question, world);
  if (reply) count_reply(question, *reply);
  return reply;
}

Result<std::string> Dialogue::ask_uncounted(const Question& question, const World& world) {
  transcript_.push_back(TranscriptLine{"Agent", question.text});
  auto reply = instructor_.answer(question, world);
  if (!reply) return reply;
  std::string text(trim(*reply));
  transcript_.push_back(TranscriptLine{"Instructor", text});
  return text;
}

void Dialogue::count_reply(const Question& question, std::string_view reply) {
  ++counts_.instructions;
  counts_.words += count_words(reply);
  if (is_yes_no(question.kind)) {
    ++counts_.yes_no;
    if (read_yes_no(reply).value_or(false)) ++counts_.yes;
  }
}

void Dialogue::say(const std::string& statement, Voice voice) {
  transcript_.push_back(TranscriptLine{"Agent", statement});
  if (instructor_.wants(voice)) instructor_.hear(statement);
}

std::string Dialogue::transcript_text() const {
  std::string out;
  for (const TranscriptLine& line : transcript_) out += line.speaker + ": " + line.text + "\n";
  return out;
}

}  // namespace apprentice
