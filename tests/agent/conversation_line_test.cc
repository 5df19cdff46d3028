// The line to the teacher (agent/conversation.h), without an agent: what
// was said ahead comes before the teacher is asked, steps said ahead
// answer only questions about the task's steps and are dropped by an
// undo, and without a teacher nothing is said.
#include "agent/conversation.h"

#include <gtest/gtest.h>

#include "agent_fixtures.h"

namespace apprentice {
namespace {

class ConversationLine : public ::testing::Test {
 protected:
  void SetUp() override { kitchen_ = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml")); }
  const World& world() const { return kitchen_.world; }
  Question asked(QuestionKind kind) const {
    Question q;
    q.kind = kind;
    q.text = "What next?";
    return q;
  }
  Scenario kitchen_;
};

TEST_F(ConversationLine, WhatWasSaidAheadComesBeforeTheTeacherIsAsked) {
  testing::CallbackInstructor teacher(testing::replies({"from the teacher"}), true);
  Dialogue dialogue(teacher);
  Conversation line(&dialogue);
  EXPECT_TRUE(line.with_person());
  line.answer_ahead("the wrench goes in the bottom drawer");
  line.steps_ahead({"then the table", "then the counter"});
  const Question step = asked(QuestionKind::kTaskStep);
  auto first = line.next_reply(step, world(), true);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->text, "the wrench goes in the bottom drawer");
  EXPECT_FALSE(first->said_ahead) << "an answer after an undo is the teacher's instruction";
  // A question about a thing's goal is not answered by a step said ahead.
  auto goal = line.next_reply(asked(QuestionKind::kSubtaskStep), world(), false);
  ASSERT_TRUE(goal);
  EXPECT_EQ(goal->text, "from the teacher");
  EXPECT_EQ(teacher.questions.size(), 1u);
  auto second = line.next_reply(step, world(), true);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->text, "then the table");
  EXPECT_TRUE(second->said_ahead);
  // An undo drops the steps said of what it undid; the teacher is asked.
  line.drop_steps_ahead();
  EXPECT_FALSE(line.next_reply(step, world(), true)) << "the teacher has nothing more to say";
  EXPECT_EQ(teacher.questions.size(), 2u);
}

TEST_F(ConversationLine, RepliesAreCountedOnlyWhenTold) {
  testing::CallbackInstructor teacher(testing::replies({"help", "the fridge"}), false);
  Dialogue dialogue(teacher);
  Conversation line(&dialogue);
  EXPECT_FALSE(line.with_person());
  const Question q = asked(QuestionKind::kSubtaskStep);
  ASSERT_TRUE(line.next_reply(q, world(), false));
  EXPECT_EQ(line.instructions(), 0) << "help is no instruction";
  auto answer = line.next_reply(q, world(), false);
  ASSERT_TRUE(answer);
  line.count(q, answer->text);
  EXPECT_EQ(line.instructions(), 1);
}

TEST_F(ConversationLine, WithoutATeacherNothingIsSaidOrCounted) {
  Conversation alone(nullptr);
  EXPECT_FALSE(alone.with_teacher());
  EXPECT_FALSE(alone.with_person());
  alone.say("nobody hears this");
  EXPECT_EQ(alone.instructions(), 0);
  EXPECT_FALSE(alone.recent_place().has_value());
  alone.named_place(*world().universe->find("fridge1"));
  EXPECT_EQ(alone.recent_place(), world().universe->find("fridge1"));
}

}  // namespace
}  // namespace apprentice
