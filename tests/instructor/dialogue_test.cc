// The dialogue counts what the instructor says the way the paper's Table 3
// does: every reply is an instruction, its words are whitespace-separated
// tokens, and a reply to a yes/no question is also a yes/no answer.
#include "instructor/dialogue.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "instructor_fixtures.h"

namespace apprentice {
namespace {

using testing::ScriptedInstructor;
using ::testing::ElementsAre;

Question question(QuestionKind kind, std::string text) {
  Question q;
  q.kind = kind;
  q.text = std::move(text);
  return q;
}

TEST(CountWords, CountsWhitespaceSeparatedTokens) {
  EXPECT_EQ(count_words(""), 0);
  EXPECT_EQ(count_words("   "), 0);
  EXPECT_EQ(count_words("yes."), 1);
  EXPECT_EQ(count_words("Tidy kitchen."), 2);
  EXPECT_EQ(count_words("  Open \t the   fridge.\n"), 3);
}

TEST(CountWords, AHyphenatedCategoryIsOneWord) {
  EXPECT_EQ(count_words("If the object is an apple-core then the goal is that the object is in the garbage."), 17);
  EXPECT_EQ(count_words("If the object is a box-of-aluminum-foil then the goal is that the object is in the pantry "
                        "and the pantry is closed."),
            22);
}

TEST(CountWords, TheTaskStructureOfTheScriptIs76WordsIn14Instructions) {
  // The fourteen task-structure instructions of a tidy-kitchen run with
  // three subtasks: the paper's Inst+Search row is 40 instructions and 603
  // words, of which these are 14 and 76.
  const std::vector<std::string> structure = {
      "Tidy kitchen.",
      "Repeat the following tasks while an object is on the table.",
      "Clear an object that is on the table.",
      "You are done.",
      "Repeat.",
      "Repeat the following tasks while an object is on the counter.",
      "Store an object that is on the counter.",
      "You are done.",
      "Repeat.",
      "Repeat the following tasks while an object is in the dish rack.",
      "Unload an object that is in the dish rack.",
      "You are done.",
      "Repeat.",
      "You are done.",
  };
  int words = 0;
  for (const std::string& s : structure) words += count_words(s);
  EXPECT_EQ(words, 76);
}

TEST(ReadYesNo, ReadsTheScriptsAnswersAndCommonVariants) {
  EXPECT_EQ(read_yes_no("yes."), true);
  EXPECT_EQ(read_yes_no("no."), false);
  EXPECT_EQ(read_yes_no("  Yes!  "), true);
  EXPECT_EQ(read_yes_no("NO"), false);
  EXPECT_EQ(read_yes_no("y"), true);
  EXPECT_EQ(read_yes_no("n."), false);
  EXPECT_EQ(read_yes_no("maybe"), std::nullopt);
  // The reader the agent answers with: a person's "sure" is a yes, counted.
  EXPECT_EQ(read_yes_no("sure"), true);
  EXPECT_EQ(read_yes_no("yep, go ahead"), true);
  EXPECT_EQ(read_yes_no("nope"), false);
  EXPECT_EQ(read_yes_no("no, the pantry"), false);
  // The agent takes "yes, in the fridge" as a yes (and reads the rest), so
  // it is counted as one.
  EXPECT_EQ(read_yes_no("yes, in the fridge"), true);
  EXPECT_EQ(read_yes_no(""), std::nullopt);
}

TEST(Dialogue, AnInstructionCountsItsWords) {
  ScriptedInstructor instructor({"If the object is a ketchup then the goal is that the object is in the fridge "
                                 "and the fridge is closed."});
  Dialogue dialogue(instructor);
  World world;
  auto reply = dialogue.ask(question(QuestionKind::kSubtaskStep, "What is the next goal or subtask of clear?"), world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{1, 22, 0, 0}));
}

TEST(Dialogue, AYesNoAnswerIsAnInstructionOfOneWordAndAYesNo) {
  ScriptedInstructor instructor({"yes.", "no.", "Yes"});
  Dialogue dialogue(instructor);
  World world;
  ASSERT_TRUE(dialogue.ask(question(QuestionKind::kConfirmGoal, "[LM] For a ketchup on the table, is the goal that "
                                                                "the ketchup is in the fridge?"), world));
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{1, 1, 1, 1}));
  ASSERT_TRUE(dialogue.ask(question(QuestionKind::kConfirmAction, "[LM] For the ketchup, should I 'Open fridge'?"), world));
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{2, 2, 2, 1}));
  ASSERT_TRUE(dialogue.ask(question(QuestionKind::kConfirmGoal, "Is it?"), world));
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{3, 3, 3, 2}));
}

TEST(Dialogue, OnlyRepliesToYesNoQuestionsAreYesNoAnswers) {
  // "yes." to a question that is not a yes/no question is an ordinary
  // instruction (the agent will not understand it, but it was said).
  ScriptedInstructor instructor({"yes."});
  Dialogue dialogue(instructor);
  World world;
  ASSERT_TRUE(dialogue.ask(question(QuestionKind::kTaskName, "What task should I learn?"), world));
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{1, 1, 0, 0}));
}

TEST(Dialogue, RepliesAreTrimmedAndTheTranscriptIsAsThePaperPrintsIt) {
  ScriptedInstructor instructor({"  Tidy kitchen.  \n", "no."});
  Dialogue dialogue(instructor);
  World world;
  auto reply = dialogue.ask(question(QuestionKind::kTaskName, "What task should I learn?"), world);
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(*reply, "Tidy kitchen.");
  dialogue.say("I cannot do that: the fridge is closed.");
  ASSERT_TRUE(dialogue.ask(question(QuestionKind::kConfirmAction, "[LM] For the milk, should I 'Pick up milk'?"), world));
  EXPECT_EQ(dialogue.transcript_text(),
            "Agent: What task should I learn?\n"
            "Instructor: Tidy kitchen.\n"
            "Agent: I cannot do that: the fridge is closed.\n"
            "Agent: [LM] For the milk, should I 'Pick up milk'?\n"
            "Instructor: no.\n");
  ASSERT_EQ(dialogue.transcript().size(), 5u);
  EXPECT_EQ(dialogue.transcript()[1].speaker, "Instructor");
  // What the agent says is heard by the instructor, and not counted.
  EXPECT_THAT(instructor.heard, ElementsAre("I cannot do that: the fridge is closed."));
  EXPECT_EQ(dialogue.counts(), (DialogueCounts{2, 3, 1, 0}));
}

TEST(Dialogue, TheQuestionReachesTheInstructorWithWhatItIsAbout) {
  ScriptedInstructor instructor({"Open the fridge."});
  Dialogue dialogue(instructor);
  World world;
  Question q = question(QuestionKind::kNextAction, "What do I do next for clear?");
  q.task = "tidy kitchen";
  q.subtask = "clear";
  q.object = 7;
  ASSERT_TRUE(dialogue.ask(q, world));
  ASSERT_EQ(instructor.questions.size(), 1u);
  EXPECT_EQ(instructor.questions[0].kind, QuestionKind::kNextAction);
  EXPECT_EQ(instructor.questions[0].subtask, "clear");
  EXPECT_EQ(instructor.questions[0].object, std::optional<ObjectId>(7));
}

TEST(Dialogue, AnInstructorWhoLeavesIsNotCounted) {
  ScriptedInstructor instructor({});
  Dialogue dialogue(instructor);
  World world;
  auto reply = dialogue.ask(question(QuestionKind::kTaskName, "What task should I learn?"), world);
  ASSERT_FALSE(reply.has_value());
  EXPECT_EQ(reply.error().code, ErrorCode::kCancelled);
  EXPECT_EQ(dialogue.counts(), DialogueCounts{});
  // The question was asked, and stays in the transcript.
  EXPECT_EQ(dialogue.transcript_text(), "Agent: What task should I learn?\n");
}

TEST(QuestionKinds, OnlyConfirmationsAreYesNoQuestions) {
  EXPECT_TRUE(is_yes_no(QuestionKind::kConfirmGoal));
  EXPECT_TRUE(is_yes_no(QuestionKind::kConfirmAction));
  EXPECT_FALSE(is_yes_no(QuestionKind::kTaskName));
  EXPECT_FALSE(is_yes_no(QuestionKind::kTaskStep));
  EXPECT_FALSE(is_yes_no(QuestionKind::kSubtaskStep));
  EXPECT_FALSE(is_yes_no(QuestionKind::kNextAction));
  EXPECT_STREQ(to_string(QuestionKind::kConfirmGoal), "confirm-goal");
  EXPECT_STREQ(to_string(QuestionKind::kNextAction), "next-action");
}

}  // namespace
}  // namespace apprentice
