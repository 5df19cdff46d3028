// The terminal instructor: a person's replies read line by line from a
// pipe or a script (and through libedit at a terminal), the agent's
// questions and prompts printed, blank lines skipped, --quiet hiding the
// agent's narration, and end of input (Ctrl-D) ending the session as
// kCancelled. (Commands such as "status" are replies the agent answers:
// tests/agent.)
#include "instructor/terminal_instructor.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "instructor/dialogue.h"
#include "instructor_fixtures.h"

namespace apprentice {
namespace {

using testing::load_or_die;
using testing::object;
using testing::source_path;
using ::testing::HasSubstr;
using ::testing::Not;

// The instructor's input: `text` through a pipe whose write end is closed,
// so reading past it is end of input.
class PipeInput {
 public:
  explicit PipeInput(const std::string& text) {
    int fds[2];
    if (pipe(fds) != 0) std::abort();
    // Pipes hold at least 4 KiB; the scripts here are far shorter.
    if (!text.empty() && write(fds[1], text.data(), text.size()) != static_cast<ssize_t>(text.size())) std::abort();
    close(fds[1]);
    file_ = fdopen(fds[0], "r");
  }
  ~PipeInput() { std::fclose(file_); }
  std::FILE* file() const { return file_; }

 private:
  std::FILE* file_;
};

Question ask_about(const World& world, QuestionKind kind, std::string text) {
  Question q;
  q.kind = kind;
  q.text = std::move(text);
  q.task = "tidy kitchen";
  q.subtask = "clear";
  q.object = object(world, "ketchup1");
  return q;
}

class TerminalInstructorTest : public ::testing::Test {
 protected:
  Scenario kitchen_ = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  std::ostringstream out_;
};

TEST_F(TerminalInstructorTest, PrintsTheQuestionAndThePromptAndEchoesTheReply) {
  PipeInput input("Tidy kitchen.\n");
  TerminalInstructor instructor(input.file(), out_);
  Question q;
  q.text = "What task should I learn?";
  auto reply = instructor.answer(q, kitchen_.world);
  ASSERT_TRUE(reply.has_value()) << reply.error().describe();
  EXPECT_EQ(*reply, "Tidy kitchen.");
  EXPECT_EQ(out_.str(), "Agent: What task should I learn?\nInstructor: Tidy kitchen.\n");
}

TEST_F(TerminalInstructorTest, ReadsWithFmemopenToo) {
  std::string text = "  Open the fridge.  \nyes.";
  std::FILE* in = fmemopen(text.data(), text.size(), "r");
  ASSERT_NE(in, nullptr);
  TerminalInstructor instructor(in, out_);
  auto first = instructor.answer(ask_about(kitchen_.world, QuestionKind::kNextAction, "What should I do next?"),
                                 kitchen_.world);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(*first, "Open the fridge.");  // trimmed
  // A last line without a newline is still a reply.
  auto second = instructor.answer(ask_about(kitchen_.world, QuestionKind::kConfirmGoal, "Is it?"), kitchen_.world);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(*second, "yes.");
  auto third = instructor.answer(ask_about(kitchen_.world, QuestionKind::kConfirmGoal, "Is it?"), kitchen_.world);
  ASSERT_FALSE(third.has_value());
  EXPECT_EQ(third.error().code, ErrorCode::kCancelled);
  std::fclose(in);
}

TEST_F(TerminalInstructorTest, BlankLinesAreNotReplies) {
  PipeInput input("\n   \nno.\n");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kConfirmGoal, "Is it?"), kitchen_.world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(*reply, "no.");
}

TEST_F(TerminalInstructorTest, CommandsAreRepliesForTheAgentToRead) {
  PipeInput input("status\n");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "What task should I learn?"),
                                 kitchen_.world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(*reply, "status");
}

TEST_F(TerminalInstructorTest, IsAPersonWhomTheAgentNeverGivesUpOn) {
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_);
  EXPECT_TRUE(instructor.is_person());
}

TEST_F(TerminalInstructorTest, QuietHidesNarrationButNotAnswersToThePerson) {
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_, TerminalOptions{true, false});
  Dialogue dialogue(instructor);
  dialogue.say("So the ketchup goes in the fridge.");
  dialogue.say("I asked a yes-or-no question.", Voice::kResponse);
  EXPECT_EQ(out_.str(), "Agent: I asked a yes-or-no question.\n");
  // The transcript keeps both.
  EXPECT_EQ(dialogue.transcript().size(), 2u);
}

TEST_F(TerminalInstructorTest, EndOfInputIsCancelled) {
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "What task should I learn?"),
                                 kitchen_.world);
  ASSERT_FALSE(reply.has_value());
  EXPECT_EQ(reply.error().code, ErrorCode::kCancelled);
}

TEST_F(TerminalInstructorTest, EndOfInputEndsThePromptLine) {
  // What is printed next (the CLI's "Stopped. ...") starts on its own line.
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_);
  Question q;
  q.text = "What task should I learn?";
  ASSERT_FALSE(instructor.answer(q, kitchen_.world).has_value());
  EXPECT_THAT(out_.str(), ::testing::EndsWith("\n"));
}

TEST_F(TerminalInstructorTest, WhatTheAgentSaysIsPrinted) {
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_);
  instructor.hear("The fridge is closed, so I cannot put the ketchup in it.");
  EXPECT_EQ(out_.str(), "Agent: The fridge is closed, so I cannot put the ketchup in it.\n");
}

TEST_F(TerminalInstructorTest, CtrlCEndsTheSessionAndIsToldApartFromEndOfInput) {
  PipeInput input("Tidy kitchen.\n");
  {
    TerminalInstructor instructor(input.file(), out_, TerminalOptions{false, true});
    EXPECT_FALSE(instructor.interrupted());
    std::raise(SIGINT);  // handled: the test goes on
    auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "What task should I learn?"),
                                   kitchen_.world);
    ASSERT_FALSE(reply.has_value());
    EXPECT_EQ(reply.error().code, ErrorCode::kCancelled);
    EXPECT_TRUE(instructor.interrupted());
  }
  // Without catch_interrupt, end of input is not an interrupt.
  PipeInput empty("");
  TerminalInstructor plain(empty.file(), out_);
  ASSERT_FALSE(plain.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "?"), kitchen_.world).has_value());
  EXPECT_FALSE(plain.interrupted());
}

// At a terminal the replies go through libedit. The test plays the person
// on the master side of a pseudo-terminal.
TEST_F(TerminalInstructorTest, ReadsThroughLineEditingAtATerminal) {
  int master = -1, slave = -1;
  if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) GTEST_SKIP() << "no pseudo-terminals here";
  std::FILE* in = fdopen(slave, "r");
  ASSERT_NE(in, nullptr);
  ASSERT_TRUE(isatty(fileno(in)));
  const std::string typed = "Tidy kitchen.\n";
  ASSERT_EQ(write(master, typed.data(), typed.size()), static_cast<ssize_t>(typed.size()));
  {
    TerminalInstructor instructor(in, out_);
    Question q;
    q.text = "What task should I learn?";
    auto reply = instructor.answer(q, kitchen_.world);
    ASSERT_TRUE(reply.has_value()) << reply.error().describe();
    EXPECT_EQ(*reply, "Tidy kitchen.");
    EXPECT_EQ(out_.str(), "Agent: What task should I learn?\n");
    // Ctrl-D on an empty line.
    const char eof = 4;
    ASSERT_EQ(write(master, &eof, 1), 1);
    auto end = instructor.answer(q, kitchen_.world);
    ASSERT_FALSE(end.has_value());
    EXPECT_EQ(end.error().code, ErrorCode::kCancelled);
  }
  std::fclose(in);
  close(master);
}

}  // namespace
}  // namespace apprentice
