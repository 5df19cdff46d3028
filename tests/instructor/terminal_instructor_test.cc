// The terminal instructor: a person's replies read line by line from a
// pipe or a script (and through libedit at a terminal), the agent's
// questions and prompts printed, "status" and "help" answered without
// consuming a reply, and end of input (Ctrl-D) ending the session as
// kCancelled.
#include "instructor/terminal_instructor.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

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
  auto first = instructor.answer(ask_about(kitchen_.world, QuestionKind::kNextAction, "What do I do next for clear?"),
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

TEST_F(TerminalInstructorTest, StatusShowsTheWorldWithoutConsumingAnAnswer) {
  PipeInput input("status\nOpen the fridge.\n");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kNextAction, "What do I do next for clear?"),
                                 kitchen_.world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(*reply, "Open the fridge.");
  const std::string out = out_.str();
  EXPECT_THAT(out, HasSubstr("Agent: What do I do next for clear?\nInstructor: status\nWorld (kitchen):\n"));
  EXPECT_THAT(out, HasSubstr("  fridge1 is closed\n"));
  EXPECT_THAT(out, HasSubstr("  on table1: "));
  EXPECT_THAT(out, HasSubstr(" ketchup1"));
  EXPECT_THAT(out, HasSubstr("Progress: task tidy kitchen, subtask clear, working on ketchup1\n"));
  EXPECT_THAT(out, ::testing::EndsWith("Instructor: Open the fridge.\n"));
}

TEST_F(TerminalInstructorTest, StatusIsNotAnInstruction) {
  PipeInput input("status\nSTATUS\nTidy kitchen.\n");
  TerminalInstructor instructor(input.file(), out_);
  Dialogue dialogue(instructor);
  Question q;
  q.text = "What task should I learn?";
  auto reply = dialogue.ask(q, kitchen_.world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{1, 2, 0, 0}));
  EXPECT_EQ(dialogue.transcript_text(), "Agent: What task should I learn?\nInstructor: Tidy kitchen.\n");
}

TEST_F(TerminalInstructorTest, HelpAndBlankLinesAreNotReplies) {
  PipeInput input("help\n\n   \nno.\n");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kConfirmGoal, "Is it?"), kitchen_.world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(*reply, "no.");
  EXPECT_THAT(out_.str(), HasSubstr("status"));
  EXPECT_THAT(out_.str(), HasSubstr("Ctrl-D"));
}

TEST_F(TerminalInstructorTest, EndOfInputIsCancelled) {
  PipeInput input("");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "What task should I learn?"),
                                 kitchen_.world);
  ASSERT_FALSE(reply.has_value());
  EXPECT_EQ(reply.error().code, ErrorCode::kCancelled);
}

TEST_F(TerminalInstructorTest, EndOfInputAfterStatusIsCancelled) {
  PipeInput input("status\n");
  TerminalInstructor instructor(input.file(), out_);
  auto reply = instructor.answer(ask_about(kitchen_.world, QuestionKind::kTaskName, "What task should I learn?"),
                                 kitchen_.world);
  ASSERT_FALSE(reply.has_value());
  EXPECT_EQ(reply.error().code, ErrorCode::kCancelled);
  EXPECT_THAT(out_.str(), HasSubstr("World (kitchen):"));
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
  instructor.hear("I cannot do that: (closed fridge1) is true.");
  EXPECT_EQ(out_.str(), "Agent: I cannot do that: (closed fridge1) is true.\n");
}

TEST_F(TerminalInstructorTest, StatusShowsWhatTheRobotHoldsAndOpenDoors) {
  World world = kitchen_.world;
  for (const char* step : {"(open fridge1)", "(pick-up ketchup1 table1)"}) {
    auto action = parse_action(*world.domain, *world.universe, step);
    ASSERT_TRUE(action.has_value());
    world.state = apply(*world.domain, world.state, *action);
  }
  std::string status = describe_status(ask_about(world, QuestionKind::kNextAction, "?"), world);
  EXPECT_THAT(status, HasSubstr("  fridge1 is open\n"));
  EXPECT_THAT(status, HasSubstr("  holding ketchup1\n"));
  EXPECT_THAT(status, Not(HasSubstr(" ketchup1\n  on")));
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
