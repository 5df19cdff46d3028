// The conversation between agent and instructor: it passes questions on,
// keeps the transcript, and counts what the instructor says the way the
// paper's Table 3 does. Every reply is an instruction, except commands to
// the agent ("help", "undo"), which the agent reads with ask_uncounted();
// an instruction's words are its whitespace-separated tokens ("apple-core"
// is one word); replies to yes/no questions are also counted as yes/no
// answers.
#pragma once

#include <string>
#include <vector>

#include "instructor/instructor.h"

namespace apprentice {

struct DialogueCounts {
  int instructions = 0;
  int words = 0;
  int yes_no = 0;  // answers to yes/no questions
  int yes = 0;     // of which yes
  friend bool operator==(const DialogueCounts&, const DialogueCounts&) = default;
};

struct TranscriptLine {
  std::string speaker;  // "Agent" or "Instructor"
  std::string text;
};

class Dialogue {
 public:
  explicit Dialogue(Instructor& instructor) : instructor_(instructor) {}

  // Asks, records and counts the reply as an instruction; the reply is
  // trimmed.
  Result<std::string> ask(const Question& question, const World& world);
  // Asks and records without counting; count_reply() counts it once the
  // agent knows it is an instruction rather than a command.
  Result<std::string> ask_uncounted(const Question& question, const World& world);
  void count_reply(const Question& question, std::string_view reply);
  // The agent says something that needs no answer.
  void say(const std::string& statement, Voice voice = Voice::kNarration);
  // An action the agent has just executed (Instructor::observe).
  void observe(const Action& action, const World& world) { instructor_.observe(action, world); }
  // Whether a person answers (see Instructor::is_person).
  bool instructor_is_person() const { return instructor_.is_person(); }

  const DialogueCounts& counts() const { return counts_; }
  const std::vector<TranscriptLine>& transcript() const { return transcript_; }
  // "Agent: ...\nInstructor: ...\n", as the paper prints dialogues.
  std::string transcript_text() const;

 private:
  Instructor& instructor_;
  DialogueCounts counts_;
  std::vector<TranscriptLine> transcript_;
};

// Words as the paper counts them: whitespace-separated tokens.
int count_words(std::string_view utterance);
// Whether a reply reads as yes or no: language::yes_or_no, the reader the
// agent answers with, so that a yes counted is a yes taken.
std::optional<bool> read_yes_no(std::string_view reply);

}  // namespace apprentice
