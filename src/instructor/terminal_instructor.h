// A person at the terminal. The agent's questions are printed, one line
// each ("Agent: ...?"), and flushed before the reply is read; the person
// types replies with line editing and history (libedit) when the input is
// a terminal, or they are read line by line from a pipe or script.
//
// Commands ("help", "status", "undo", ...) are replies like any other: the
// agent reads them (language/reply.h) and answers them itself. Blank lines
// are skipped. End of input (Ctrl-D) ends the session cleanly: answer()
// returns kCancelled, and everything learned so far has already been
// stored. With `catch_interrupt`, Ctrl-C does the same and interrupted()
// says so, so that the caller can tell the person and exit with 130.
#pragma once

#include <csignal>
#include <cstdio>
#include <iosfwd>
#include <string>

#include "instructor/instructor.h"

namespace apprentice {

struct TerminalOptions {
  // Print only questions and answers to what the person typed (help,
  // status, why a reply cannot be used), not the agent's narration.
  bool quiet = false;
  // Handle SIGINT while this instructor lives (the previous handler is put
  // back by the destructor): Ctrl-C ends the session as end of input does.
  bool catch_interrupt = false;
};

class TerminalInstructor final : public Instructor {
 public:
  // Reads from `in` and writes to `out`; uses libedit only if `in` is a
  // terminal. Neither is owned.
  TerminalInstructor(std::FILE* in, std::ostream& out, TerminalOptions options = {});
  ~TerminalInstructor() override;
  TerminalInstructor(const TerminalInstructor&) = delete;
  TerminalInstructor& operator=(const TerminalInstructor&) = delete;

  Result<std::string> answer(const Question& question, const World& world) override;
  void hear(std::string_view statement) override;
  bool wants(Voice voice) const override { return !options_.quiet || voice != Voice::kNarration; }
  bool is_person() const override { return true; }

  // Whether the person pressed Ctrl-C (only with catch_interrupt).
  bool interrupted() const;

 private:
  Result<std::string> read_line(const char* prompt);

  std::FILE* in_;
  std::ostream& out_;
  TerminalOptions options_;
  bool interactive_;
  struct sigaction previous_interrupt_handler_ {};
};

}  // namespace apprentice
