// A teaching session at a terminal, checked line for line: a mistyped
// reply, help, a wrong goal undone, Ctrl-C, and the session resumed from
// the knowledge store. The expected screens below are what a person sees
// (the terminal echoes what they type after "Instructor: ").
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent_fixtures.h"
#include "common/scratch.h"
#include "pty.h"

namespace apprentice {
namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// Types each reply when the agent asks (or the key, for "\x03"), in order.
std::string session(const std::vector<std::string>& args, const std::vector<std::string>& keys, int* exit_code) {
  testing::Terminal terminal(args);
  EXPECT_TRUE(terminal.started());
  size_t from = 0;
  for (const std::string& key : keys) {
    std::string question = terminal.next_question(from);
    EXPECT_FALSE(question.empty()) << "the agent stopped asking before " << key << ":\n" << terminal.screen();
    if (question.empty()) break;
    from = terminal.screen().size();
    terminal.type(key == "\x03" ? key : key + "\r");
  }
  *exit_code = terminal.wait();
  return terminal.screen();
}

const char* const kFirstSession = R"(Teaching in two-objects (inst+search4). Answer in your own words; type help at any question. Ctrl-D or quit stops and keeps what you taught.
Agent: What task should I learn?
Instructor: Tidy kitchen.
Agent: What should I do first to tidy the kitchen?
Instructor: Repeat the following tasks while an object is on the table.
Agent: So I repeat the next steps while something is on the table.
Agent: What should I do next to tidy the kitchen?
Instructor: Clear an object that is on the tabel.
Agent: I do not know the word "tabel". Did you mean "table"? You could say, for example, "clear the table" or "that's all".
Agent: What should I do next to tidy the kitchen?
Instructor: help
Agent: I asked: What should I do next to tidy the kitchen?
Agent: Tell me the next step of the task: a subtask with the place it is about, or that the task is done, for example "clear the table" or "that's all".
Agent: You can also type: help; status (what I see and what I have learned); undo (forget what your last answer taught me); forget <kind of object> (forget where that kind of thing goes); quit, or Ctrl-D (stop; what I learned is kept).
Agent: What should I do next to tidy the kitchen?
Instructor: Clear an object that is on the table.
Agent: So I clear one thing on the table at a time.
Agent: Where should the ketchup on the table go?
Instructor: If the object is a ketchup then the goal is that the object is in the garbage.
Agent: So the ketchup goes in the garbage.
Agent: I put the ketchup in the garbage.
Agent: Is there more to clear on the table, or is that all?
Instructor: undo
Agent: I forgot what you told me last: "If the object is a ketchup then the goal is that the object is in the garbage."
Agent: To put things back as they were, I took the ketchup out of the garbage and put it on the table.
Agent: Where should the ketchup on the table go?
Instructor: If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.
Agent: So the ketchup goes in the fridge, and the fridge ends closed.
Agent: I opened the fridge, put the ketchup in it, and closed it.
Agent: Is there more to clear on the table, or is that all?
Instructor: 
Interrupted. What you taught me is kept in STORE.
)";

const char* const kResumedSession = R"(Teaching in two-objects (inst+search4). Answer in your own words; type help at any question. Ctrl-D or quit stops and keeps what you taught.
Agent: What task should I learn?
Instructor: Tidy kitchen.
Agent: I know how to tidy the kitchen; I will ask only about what is new.
Agent: Next, the ketchup on the table: it goes in the fridge, and the fridge ends closed.
Agent: I opened the fridge, put the ketchup in it, and closed it.
Agent: Where should the paper plate on the table go?
Instructor: If the object is a paper-plate then the goal is that the object is in the garbage.
Agent: So the paper plate goes in the garbage.
Agent: I put the paper plate in the garbage.
Agent: There is nothing left on the table.
Agent: What should I do next to tidy the kitchen?
Instructor: You are done.
Agent: So the task is done.
The task is learned: 3 of 3 parts of the goal are met, after 3 instructions.
What you taught me is kept in STORE.
)";

TEST(Transcript, MistakeHelpUndoCtrlCAndResumeAtATerminal) {
  testing::ScratchDir dir;
  const std::string store = (dir / "kitchen.sqlite").string();
  const std::vector<std::string> args = {APPRENTICE_BINARY, "teach", "--scenario",
                                         testing::source_path("tests/agent/data/two-objects.yaml").string(),
                                         "--knowledge", store};
  int code = 0;
  std::string first = session(args,
                              {"Tidy kitchen.", "Repeat the following tasks while an object is on the table.",
                               "Clear an object that is on the tabel.", "help", "Clear an object that is on the table.",
                               "If the object is a ketchup then the goal is that the object is in the garbage.", "undo",
                               "If the object is a ketchup then the goal is that the object is in the fridge and the "
                               "fridge is closed.",
                               "\x03"},
                              &code);
  EXPECT_EQ(first, replaced(kFirstSession, "STORE", store));
  EXPECT_EQ(code, 130);
  std::string second =
      session(args,
              {"Tidy kitchen.", "If the object is a paper-plate then the goal is that the object is in the garbage.",
               "You are done."},
              &code);
  EXPECT_EQ(second, replaced(kResumedSession, "STORE", store));
  EXPECT_EQ(code, 0);
}

}  // namespace
}  // namespace apprentice
