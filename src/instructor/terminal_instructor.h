// A person at the terminal. The agent's questions are printed; the person
// types replies with line editing and history (libedit) when the input is a
// terminal, or they are read line by line from a pipe or script.
//
// Typing "status" shows the world and the progress instead of answering;
// "help" lists what can be typed. End of input (Ctrl-D) ends the session
// cleanly: answer() returns kCancelled and everything learned so far has
// already been stored.
#pragma once

#include <cstdio>
#include <iosfwd>
#include <string>

#include "instructor/instructor.h"

namespace apprentice {

class TerminalInstructor final : public Instructor {
 public:
  // Reads from `in` and writes to `out`; uses libedit only if `in` is a
  // terminal. Neither is owned.
  TerminalInstructor(std::FILE* in, std::ostream& out);
  ~TerminalInstructor() override;

  Result<std::string> answer(const Question& question, const World& world) override;
  void hear(std::string_view statement) override;

 private:
  Result<std::string> read_line(const char* prompt);
  void print_status(const Question& question, const World& world);

  std::FILE* in_;
  std::ostream& out_;
  bool interactive_;
};

// The world and the progress, as "status" prints them.
std::string describe_status(const Question& question, const World& world);

}  // namespace apprentice
