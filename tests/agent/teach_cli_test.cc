// `apprentice teach` end to end, as a person would use it: the real binary,
// the instructor's replies typed on its stdin, the dialogue read from its
// stdout. The scenario is a small kitchen of this directory: a ketchup for
// the fridge and a paper-plate for the garbage.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent_fixtures.h"
#include "knowledge/store.h"
#include "common/scratch.h"
#include "process.h"

namespace apprentice {
namespace {

namespace fs = std::filesystem;
using testing::Process;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::Not;

using testing::kKetchupGoal;
using testing::kPaperPlateGoal;
const char* const kBanner =
    "Teaching in two-objects (inst+search4). Answer in your own words; type help at any question. Ctrl-D or quit "
    "stops and keeps what you taught.\n";

// What the instructor says for the two-object kitchen, in order.
std::vector<std::string> full_script() {
  return {"Tidy kitchen.",
          "Repeat the following tasks while an object is on the table.",
          "Clear an object that is on the table.",
          kKetchupGoal,
          "You are done.",
          "Repeat.",
          kPaperPlateGoal,
          "You are done."};
}

// Each test has a fresh directory of its own (testing::ScratchTest::dir_),
// so that runs in parallel never share a store.
class Teach : public testing::ScratchTest {
 protected:
  std::vector<std::string> teach_args(const std::string& condition = "inst+search4") const {
    return {APPRENTICE_BINARY, "teach", "--scenario", scenario_.string(), "--knowledge", knowledge().string(),
            "--condition", condition};
  }
  fs::path knowledge() const { return dir_ / "knowledge.sqlite"; }
  std::string kept() const { return "What you taught me is kept in " + knowledge().string() + ".\n"; }

  Knowledge stored() const { return stored(scenario_); }
  Knowledge stored(const fs::path& scenario_file) const {
    Scenario scenario = testing::load_or_die(scenario_file);
    auto store = KnowledgeStore::open(knowledge());
    EXPECT_TRUE(store.has_value()) << (store ? "" : store.error().describe());
    if (!store) return {};
    auto loaded = store->load(*scenario.world.domain);
    EXPECT_TRUE(loaded.has_value()) << (loaded ? "" : loaded.error().describe());
    return loaded ? std::move(*loaded) : Knowledge{};
  }

  fs::path scenario_ = testing::source_path("tests/agent/data/two-objects.yaml");
};

TEST_F(Teach, LearnsTheTaskFromAScriptOnStdinSayingWhatItUnderstoodAndDid) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.started());
  ASSERT_TRUE(teach.write(testing::typed_lines(full_script())));
  int code = teach.wait();
  EXPECT_EQ(code, 0) << teach.out() << teach.err();
  EXPECT_EQ(teach.out(),
            std::string(kBanner) +
                "Agent: What task should I learn?\n"
                "Instructor: Tidy kitchen.\n"
                "Agent: What should I do first to tidy the kitchen?\n"
                "Instructor: Repeat the following tasks while an object is on the table.\n"
                "Agent: So I repeat the next steps while something is on the table.\n"
                "Agent: What should I do next to tidy the kitchen?\n"
                "Instructor: Clear an object that is on the table.\n"
                "Agent: So I clear one thing on the table at a time.\n"
                "Agent: Where should the ketchup on the table go?\n"
                "Instructor: " + kKetchupGoal + "\n"
                "Agent: So the ketchup goes in the fridge, and the fridge ends closed.\n"
                "Agent: I opened the fridge, put the ketchup in it, and closed it.\n"
                "Agent: Is there more to clear on the table, or is that all?\n"
                "Instructor: You are done.\n"
                "Agent: So that is all there is to clear for one thing.\n"
                "Agent: What should I do next to tidy the kitchen?\n"
                "Instructor: Repeat.\n"
                "Agent: So I clear everything else on the table the same way.\n"
                "Agent: Where should the paper plate on the table go?\n"
                "Instructor: " + kPaperPlateGoal + "\n"
                "Agent: So the paper plate goes in the garbage.\n"
                "Agent: I put the paper plate in the garbage.\n"
                "Agent: There is nothing left on the table.\n"
                "Agent: What should I do next to tidy the kitchen?\n"
                "Instructor: You are done.\n"
                "Agent: So the task is done.\n"
                "The task is learned: 3 of 3 parts of the goal are met, after 8 instructions.\n" + kept());
  Knowledge knowledge = stored();
  EXPECT_EQ(knowledge.goals.size(), 2u);
  ASSERT_EQ(knowledge.tasks.size(), 1u);
  EXPECT_EQ(knowledge.tasks[0].name, "tidy kitchen");
}

TEST_F(Teach, QuietKeepsOnlyTheQuestionsAndTheSummary) {
  // The world given first, without --scenario, as a newcomer types it.
  std::vector<std::string> args = {APPRENTICE_BINARY, "teach", scenario_.string(), "--knowledge",
                                   knowledge().string(), "--quiet"};
  Process teach(args);
  ASSERT_TRUE(teach.write(testing::typed_lines(full_script())));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), Not(HasSubstr("Teaching in")));
  EXPECT_THAT(teach.out(), Not(HasSubstr("Agent: So ")));
  EXPECT_THAT(teach.out(), Not(HasSubstr("Agent: I opened")));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the ketchup on the table go?\nInstructor: "));
  EXPECT_THAT(teach.out(), EndsWith("The task is learned: 3 of 3 parts of the goal are met, after 8 instructions.\n" + kept()));
}

TEST_F(Teach, TheInstructorTeachesActionsWithoutSearchAndRefusalsArePlainEnglish) {
  Process teach(teach_args("instruction"));
  std::vector<std::string> script = {"Tidy kitchen.",
                                     "Repeat the following tasks while an object is on the table.",
                                     "Clear an object that is on the table.",
                                     kKetchupGoal,
                                     "Put the ketchup in the fridge.",  // not holding it yet
                                     "Open the fridge.",
                                     "Pick up the ketchup.",
                                     "Put the ketchup in the fridge.",
                                     "Close the fridge.",
                                     "You are done.",
                                     "Repeat.",
                                     kPaperPlateGoal,
                                     "Pick up the paper-plate.",
                                     "Put the paper-plate in the garbage.",
                                     "You are done."};
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: What should I do next so that the ketchup is in the fridge and the fridge "
                                     "is closed?\nInstructor: Put the ketchup in the fridge.\n"
                                     "Agent: I am not holding the ketchup, so I cannot put it in the fridge.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: Close the fridge.\n"
                                     "Agent: I opened the fridge, put the ketchup in it, and closed it.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 15 instructions."));
}

TEST_F(Teach, HelpAndStatusAnswerThePersonAndAreNotInstructions) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  script.insert(script.begin() + 3, {"help", "status"});
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string question = "Agent: Where should the ketchup on the table go?\n";
  EXPECT_THAT(teach.out(), HasSubstr(question + "Instructor: help\n"
                                     "Agent: I asked: Where should the ketchup on the table go?\n"
                                     "Agent: Tell me where it goes, and anything else that should be so when it is put "
                                     "away, for example "));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: You can also type: help; status (what I see and what I have learned); undo "
                                     "(forget what your last answer taught me); forget <kind of object>"));
  // After help, the question comes again.
  EXPECT_THAT(teach.out(), HasSubstr(".\n" + question + "Instructor: status\n"
                                     "Agent: I see this: the fridge is closed. On the table: the ketchup and the paper "
                                     "plate.\n"
                                     "Agent: I am learning to tidy the kitchen; now I clear what is on the table, asking "
                                     "about the ketchup. So far I know 0 goals and 0 rules, after 3 instructions this "
                                     "session.\n" +
                                     question + "Instructor: " + kKetchupGoal + "\n"));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 8 instructions."));
}

TEST_F(Teach, UndoForgetsTheLastGoalInMemoryAndStoreAndPutsTheWorldBack) {
  Process teach(teach_args());
  const char* wrong = "If the object is a ketchup then the goal is that the object is in the garbage.";
  std::vector<std::string> script = {"Tidy kitchen.",
                                     "Repeat the following tasks while an object is on the table.",
                                     "Clear an object that is on the table.",
                                     wrong,
                                     "undo",
                                     kKetchupGoal,
                                     "You are done.",
                                     "Repeat.",
                                     kPaperPlateGoal,
                                     "You are done."};
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(),
              HasSubstr("Agent: I put the ketchup in the garbage.\n"
                        "Agent: Is there more to clear on the table, or is that all?\n"
                        "Instructor: undo\n"
                        "Agent: I forgot what you told me last: \"" + std::string(wrong) + "\"\n"
                        "Agent: To put things back as they were, I took the ketchup out of the garbage and put it on "
                        "the table.\n"
                        "Agent: Where should the ketchup on the table go?\n"));
  // "undo" is not an instruction; the wrong goal was one.
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 9 instructions."));
  Knowledge knowledge = stored();
  ASSERT_EQ(knowledge.goals.size(), 2u);
  for (const GoalKnowledge& g : knowledge.goals.all()) {
    if (g.key.category == "ketchup") {
      EXPECT_THAT(g.provenance.source, HasSubstr("fridge"));
    }
  }
}

TEST_F(Teach, UndoOfAStepOfTheTaskStructureAsksForItAgain) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  script.insert(script.begin() + 3, {"undo", "Clear an object that is on the table."});
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the ketchup on the table go?\n"
                                     "Instructor: undo\n"
                                     "Agent: I forgot what you told me last: \"Clear an object that is on the table.\"\n"
                                     "Agent: What should I do next to tidy the kitchen?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 9 instructions."));
  EXPECT_EQ(stored().tasks.at(0).subtasks.size(), 1u);
}

TEST_F(Teach, ForgetAKindOfObjectForgetsWhereItGoes) {
  // Teach the ketchup's goal, forget it, and end: the store no longer has it.
  Process teach(teach_args());
  std::vector<std::string> script = {full_script()[0], full_script()[1], full_script()[2], kKetchupGoal,
                                     "forget zebra", "forget ketchups", "quit"};
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: I have not learned where to put zebra, so there is nothing to forget.\n"));
  // A plural names the kind too.
  EXPECT_THAT(teach.out(), HasSubstr("Agent: I forgot where the ketchup goes; I will ask when I meet one.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Stopped: 2 of 3 parts of the goal are met, after 4 instructions.\n"));
  EXPECT_EQ(stored().goals.size(), 0u);
}

TEST_F(Teach, CtrlDMidWayStopsCleanlyAndTeachingAgainAsksOnlyWhatIsNew) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  // Answer up to the ketchup's goal, wait for the agent to do it and ask
  // what comes next, then press Ctrl-D.
  size_t seen = 0;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(teach.read_until("Instructor: ", seen)) << teach.out() << teach.err();
    seen = teach.out().rfind("Instructor: ") + 1;
    ASSERT_TRUE(teach.write(script[i] + "\n"));
  }
  ASSERT_TRUE(teach.read_until("Agent: Is there more to clear on the table, or is that all?\nInstructor: "))
      << teach.out() << teach.err();
  teach.close_stdin();
  int code = teach.wait();
  EXPECT_EQ(code, 1) << "the goal was not reached: " << teach.out() << teach.err();
  // A clean message on its own line, naming what is not done, no error.
  EXPECT_THAT(teach.out(), EndsWith("Agent: Is there more to clear on the table, or is that all?\nInstructor: \n"
                                    "Stopped: 2 of 3 parts of the goal are met, after 4 instructions.\n"
                                    "Not done: the paper plate should be in the garbage.\n" +
                                    kept()));
  EXPECT_THAT(teach.err(), Not(HasSubstr("rror")));
  // The ketchup's goal and the task's structure were kept.
  Knowledge knowledge = stored();
  ASSERT_EQ(knowledge.goals.size(), 1u);
  EXPECT_EQ(knowledge.goals.all()[0].key.category, "ketchup");
  ASSERT_EQ(knowledge.tasks.size(), 1u);
  EXPECT_EQ(knowledge.tasks[0].subtasks.size(), 1u);

  // Teaching again with that knowledge: the agent says it knows the task,
  // does it, and asks only about the paper plate and what comes next.
  Process again(teach_args());
  ASSERT_TRUE(again.write(testing::typed_lines({"Tidy kitchen.", kPaperPlateGoal, "You are done."})));
  EXPECT_EQ(again.wait(), 0) << again.out() << again.err();
  EXPECT_THAT(again.out(), HasSubstr("Instructor: Tidy kitchen.\n"
                                     "Agent: I know how to tidy the kitchen; I will ask only about what is new.\n"
                                     "Agent: Next, the ketchup on the table: it goes in the fridge, and the fridge ends "
                                     "closed.\n"
                                     "Agent: I opened the fridge, put the ketchup in it, and closed it.\n"
                                     "Agent: Where should the paper plate on the table go?\n"));
  EXPECT_THAT(again.out(), HasSubstr("Agent: What should I do next to tidy the kitchen?\n"));
  EXPECT_THAT(again.out(), HasSubstr("The task is learned: 3 of 3 parts of the goal are met, after 3 instructions."));
  EXPECT_THAT(again.out(), Not(HasSubstr(kKetchupGoal)));
  EXPECT_EQ(stored().goals.size(), 2u);
}

TEST_F(Teach, EndOfInputBeforeAnythingIsStillCleanAndNamesWhatIsNotDone) {
  // Only the fridge's door holds already (it starts closed).
  Process teach(teach_args());
  EXPECT_EQ(teach.wait(), 1);
  EXPECT_THAT(teach.out(), EndsWith("Instructor: \nStopped: 1 of 3 parts of the goal is met, after 0 instructions.\n"
                                    "Not done: the ketchup should be in the fridge.\n"
                                    "Not done: the paper plate should be in the garbage.\n" +
                                    kept()));
}

TEST_F(Teach, TheSummaryTellsLookAlikesApartByWhereTheyWereAndSaysRepeatsOnce) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/tidy-kitchen.yaml").string()});
  ASSERT_TRUE(teach.write("tidy the kitchen\nquit\n"));
  EXPECT_EQ(teach.wait(), 1);
  // Two mugs start on the counter and in the dish rack; both ceramic plates
  // on the table.
  EXPECT_THAT(teach.out(), HasSubstr("Not done: the mug from the counter should be in the dishwasher.\n"
                                     "Not done: the half and half should be in the fridge.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Not done: the mug from the dish rack should be in the cupboard.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Not done: the ceramic plate should be in the dishwasher (2 of them).\n"));
}

TEST_F(Teach, LeaveItAndSameAsAKindNotLearnedAnswerAGoalQuestion) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "clear the table", "same as the paper plate", "leave it", "garbage",
                                 "You are done."})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: same as the paper plate\n"
                                     "Agent: I have not learned where the paper plate goes yet. Where should the ketchup "
                                     "go? You could say"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: leave it\nAgent: I will leave the ketchup on the table as it is.\n"
                                     "Agent: Where should the paper plate on the table go?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Not done: the ketchup should be in the fridge.\n"));
}

TEST_F(Teach, SameAsALearnedKindTakesItsGoal) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "clear the table", kKetchupGoal, "same as the ketchup.", "You are done."})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: same as the ketchup.\n"
                                     "Agent: So the paper plate goes in the fridge, and the fridge ends closed.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Not done: the paper plate should be in the garbage.\n"));
}

// Three slips a person found teaching the garage: "the garage is a mess"
// named a task "garage is mess" ("garage" is a verb too); "same as the
// hammer, and shut the drawer afterwards" asked which drawer and then was
// not understood; the status said "the screwdriver and the screwdriver".
TEST_F(Teach, AGarageTaughtAsAPersonTalks) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/tidy-garage.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"the garage is a mess, let's tidy it up", "clear the workbench",
                                 "put the hammer in the top drawer and close it",
                                 "same as the hammer, and shut the drawer afterwards", "status", "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: What should I do first to tidy the garage?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: same as the hammer, and shut the drawer afterwards\n"
                                     "Agent: So the screwdriver goes in the top drawer, and the top drawer ends closed.\n"));
  EXPECT_THAT(teach.out(), Not(HasSubstr("Which drawer")));
  EXPECT_THAT(teach.out(), HasSubstr(" In the top drawer: the hammer and two screwdrivers."));
}

// A whole playroom in a parent's words: a subject before the task ("the
// kids left a mess", where "kid" is a verb too), "pick up" as a subtask,
// "the blue one", "same as the book on the floor", "go with the blocks".
// Before these readings the session stalled at the toy car.
TEST_F(Teach, APlayroomTaughtAsAPersonTalks) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/playroom.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"the kids left a mess in here. can you tidy up the playroom?",
                                 "first pick up everything off the floor", "blocks go in the red bin",
                                 "the cars go into the blue one", "the teddy goes in the toy chest, and close the lid",
                                 "books belong on the bookshelf", "the sock goes in the hamper", "ok now empty the crates",
                                 "balls go in the green bin", "the doll goes in the toy chest too, and shut it",
                                 "same as the book on the floor", "crayons go with the blocks", "that's it"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: What should I do first to tidy the playroom?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: I took \"pick up\" as clearing.\nAgent: So I clear what is on the floor, one thing at a time.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: the cars go into the blue one\nAgent: So the toy car goes in the blue bin.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: same as the book on the floor\nAgent: So the picture book goes on the bookshelf.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: crayons go with the blocks\nAgent: So the crayon goes in the red bin.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("The task is learned: 14 of 14 parts of the goal are met, after 13 instructions.\n"));
}

// Two parts of the task said in one reply: the second is taken when the
// first is done, without asking again, and counts as no further
// instruction (the same playroom, 12 replies instead of 13).
TEST_F(Teach, TwoPartsSaidInOneReplyAreDoneInTurn) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/playroom.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"the kids left a mess in here. can you tidy up the playroom?",
                                 "first pick up everything off the floor, then empty the crates",
                                 "blocks go in the red bin", "the cars go into the blue one",
                                 "the teddy goes in the toy chest, and close the lid", "books belong on the bookshelf",
                                 "the sock goes in the hamper", "balls go in the green bin",
                                 "the doll goes in the toy chest too, and shut it", "same as the book on the floor",
                                 "crayons go with the blocks", "that's it"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: There is nothing left on the floor.\n"
                                     "Agent: So I empty what is in the crates, one thing at a time.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("The task is learned: 14 of 14 parts of the goal are met, after 12 instructions.\n"));
}

// "we're done" before any part of the task is taught is not the end of
// the lesson (the summary said "The task is learned" with nothing learned).
TEST_F(Teach, DoneBeforeAnyPartOfTheTaskIsAskedAgain) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "we're done", "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: we're done\n"
                                     "Agent: I have not been told any part of the task yet, so it cannot be done."));
  EXPECT_THAT(teach.out(), Not(HasSubstr("The task is learned")));
  EXPECT_THAT(teach.out(), HasSubstr("Stopped: "));
}

TEST_F(Teach, WithoutAStoreItSaysNothingWasSavedAndHowToKeepIt) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", scenario_.string()});
  ASSERT_TRUE(teach.write(testing::typed_lines(full_script())));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), EndsWith("Nothing was saved. To keep what you teach, give a knowledge store: apprentice teach --scenario " +
                                    scenario_.string() + " --knowledge FILE (for example kitchen.sqlite).\n"));
}

TEST_F(Teach, CtrlCSaysWhatWasKeptAndExits130) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "Repeat the following tasks while an object is on the table.",
                                 "Clear an object that is on the table.", kKetchupGoal})));
  ASSERT_TRUE(teach.read_until("Agent: Is there more to clear on the table, or is that all?\nInstructor: "))
      << teach.out() << teach.err();
  teach.interrupt();
  EXPECT_EQ(teach.wait(), 130) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), EndsWith("or is that all?\nInstructor: \nInterrupted. " + kept()));
  EXPECT_EQ(teach.err(), "");
  EXPECT_EQ(stored().goals.size(), 1u);
}

TEST_F(Teach, RepliesTheAgentCannotUseAreSaidSoWithExamplesAndAskedAgain) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  script.insert(script.begin() + 3, "If the object is a ketchup then the goal is that the object is in the moon.");
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  // The agent said why, with replies that would work, and asked again; the
  // unusable reply still counts.
  EXPECT_THAT(teach.out(), ::testing::ContainsRegex("in the moon\\.\nAgent: [^\n]+ You could say, for example, \"[^\n]+\n"
                                                    "Agent: Where should the ketchup on the table go\\?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 9 instructions."));
}

TEST_F(Teach, APersonIsNeverGivenUpOn) {
  // Many more unusable replies than a program is allowed: the agent keeps
  // asking, and the task is still learned.
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  for (int i = 0; i < 6; ++i) script.insert(script.begin() + 3, "blah blah");
  ASSERT_TRUE(teach.write(testing::typed_lines(script)));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 14 instructions."));
}

// Said ahead: a goal for another thing this subtask will come to is learned
// for its kind, the question comes again, and the thing is put away from
// memory when its turn comes (the paper plate is not asked about).
TEST_F(Teach, AGoalForAThingStillToComeIsLearnedForWhenItComes) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "Repeat the following tasks while an object is on the table.",
                                 "Clear an object that is on the table.",
                                 "the goal is that the paper-plate is in the garbage.", kKetchupGoal, "You are done.",
                                 "You are done."})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the ketchup on the table go?\n"
                                     "Instructor: the goal is that the paper-plate is in the garbage.\n"
                                     "Agent: So the paper plate goes in the garbage. I will do that when I come to it.\n"
                                     "Agent: Where should the ketchup on the table go?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Next, the paper plate on the table: it goes in the garbage.\n"));
  EXPECT_THAT(teach.out(), Not(HasSubstr("Where should the paper plate")));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 parts of the goal are met, after 7 instructions."));
  EXPECT_EQ(stored().goals.size(), 2u);
}

TEST_F(Teach, UndoForgetsAGoalSaidAhead) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.write(testing::typed_lines({"Tidy kitchen.", "clear the table", "the paper plate goes in the garbage", "undo",
                                 kKetchupGoal, "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: undo\n"
                                     "Agent: I forgot what you told me last: \"the paper plate goes in the garbage\".\n"
                                     "Agent: Where should the ketchup on the table go?\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the paper plate on the table go?\n"));
  Knowledge knowledge = stored();
  ASSERT_EQ(knowledge.goals.size(), 1u);
  EXPECT_EQ(knowledge.goals.all().front().key.category, "ketchup");
}

// A laundry room in a person's words: "same again" before anything was
// taught, a thing of a later subtask, the jeans said ahead, "socks too",
// "toss it", a place with no verb and then "clear it", "same again" for
// the bleach, "same as the tissue".
TEST_F(Teach, ALaundryTaughtAsAPersonTalks) {
  const fs::path laundry = testing::source_path("data/scenarios/laundry-room.yaml");
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", laundry.string(), "--knowledge", knowledge().string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"let's do the laundry", "sort the baskets", "same again",
                                 "the detergent goes on the high shelf", "the jeans go in the hamper",
                                 "towels go in the washer", "socks too", "the sweater goes on the low shelf", "toss it",
                                 "now the folding table", "clear it", "put it on the high shelf", "same again",
                                 "the iron goes on the low shelf", "put it in the cupboard and close it",
                                 "same as the tissue", "that's it"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: same again\nAgent: I have not put anything away yet, so I do not know what "
                             "\"same again\" refers to. Where should the towel go?"));
  EXPECT_THAT(out, HasSubstr("Instructor: the detergent goes on the high shelf\nAgent: I will ask about the detergent "
                             "when I come to it; now I sort what is in the baskets. Where should the towel go?"));
  EXPECT_THAT(out, HasSubstr("Instructor: the jeans go in the hamper\n"
                             "Agent: So the jeans go in the hamper. I will do that when I come to them.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: socks too\nAgent: So the sock goes in the washer.\n"));
  EXPECT_THAT(out, HasSubstr("Agent: Next, the jeans in the blue basket: they go in the hamper.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: clear it\nAgent: So I clear what is on the folding table, one thing at a time.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: same again\nAgent: So the bleach goes on the high shelf.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: same as the tissue\nAgent: So the lint goes in the wastebasket.\n"));
  EXPECT_THAT(out, HasSubstr("The task is learned: 14 of 14 parts of the goal are met, after 17 instructions.\n"));
  // A goal for each of the ten kinds, the jeans' among them.
  Knowledge knowledge = stored(laundry);
  EXPECT_EQ(knowledge.goals.size(), 10u);
}

// The kitchen of the paper in a person's words: a list of kinds in one
// reply, "same for the fork" (a partial name), "glasses too", "milk as well"
// said ahead while asked about the fork, "same with the pop tarts", and
// "paper plate in the trash" ("trash" is a verb too).
TEST_F(Teach, AKitchenTaughtInListsAndEllipses) {
  const fs::path kitchen = testing::source_path("data/scenarios/tidy-kitchen.yaml");
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", kitchen.string(), "--knowledge", knowledge().string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"hey, can you help me clean up the kitchen?", "let's start by clearing off the table",
                                 "plates and glasses go in the dishwasher, close it", "same for the fork",
                                 "the ketchup goes in the fridge, close the door", "milk as well",
                                 "the cereal box goes in the pantry and shut it", "same with the pop tarts",
                                 "paper plate in the trash", "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: plates and glasses go in the dishwasher, close it\n"
                             "Agent: So the ceramic plate goes in the dishwasher, and the dishwasher ends closed.\n"
                             "Agent: The same goes for the glass tumbler, when I come to it.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: same for the fork\n"
                             "Agent: So the metal fork goes in the dishwasher, and the dishwasher ends closed.\n"));
  EXPECT_THAT(out, HasSubstr("Agent: Next, the glass tumbler on the table: it goes in the dishwasher, and the "
                             "dishwasher ends closed.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: same with the pop tarts\n"
                             "Agent: So the pop tart box goes in the pantry, and the pantry ends closed.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: paper plate in the trash\nAgent: So the paper plate goes in the garbage.\n"));
  EXPECT_THAT(out, Not(HasSubstr("I didn't catch")));
  // Each kind taught once, the glass tumbler's from the list.
  Knowledge knowledge = stored(kitchen);
  std::vector<std::string> kinds;
  for (const GoalKnowledge& g : knowledge.goals.all()) kinds.push_back(g.key.category);
  EXPECT_THAT(kinds, ::testing::UnorderedElementsAre("ceramic-plate", "glass-tumbler", "metal-fork", "ketchup", "milk",
                                                     "cereal-box", "pop-tart-box", "paper-plate"));
}

// "the milk too", asked about the fork right after the plate's goal: the
// milk, still to come, gets the plate's goal ahead, and the fork is asked
// about again.
TEST_F(Teach, ThingsTooSaidOfAnotherThingStillToComeIsLearnedAhead) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/tidy-kitchen.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the kitchen", "clear the table", "put it in the dishwasher and close it",
                                 "the milk too", "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the metal fork on the table go?\n"
                                     "Instructor: the milk too\n"
                                     "Agent: So the milk goes in the dishwasher, and the dishwasher ends closed. I will "
                                     "do that when I come to it.\n"
                                     "Agent: Where should the metal fork on the table go?\n"));
}

// A garage taught place by place: the workbench alone, as the first part,
// is cleared, and said so; the buckets alone are asked about ("empty them"
// then names the part), and are both buckets; the hammer said at the
// task's question is not a part of it.
TEST_F(Teach, AGarageTaughtPlaceByPlace) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/tidy-garage.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"time to tidy the garage", "the hammer goes in the top drawer", "the workbench first",
                                 "hammer and screwdrivers in the top drawer, close it",
                                 "wrench and tape measure go in the bottom drawer and close it", "paint on the shelf",
                                 "throw the rag away", "then the buckets", "empty them",
                                 "sponges, spray bottles and glue in the cabinet, close the door",
                                 "paint can on the shelf", "sandpaper in the bottom drawer, close it", "done"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: the hammer goes in the top drawer\n"
                             "Agent: There is nothing in the top drawer now. First tell me the parts of the task"));
  EXPECT_THAT(out, HasSubstr("Instructor: the workbench first\n"
                             "Agent: I took \"the workbench first\" as clearing the workbench.\n"
                             "Agent: So I clear what is on the workbench, one thing at a time.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: then the buckets\n"
                             "Agent: What should I do with the things in the buckets? You could say, for example, "
                             "\"clear the buckets\""));
  EXPECT_THAT(out, HasSubstr("Instructor: empty them\nAgent: So I empty what is in the buckets, one thing at a time.\n"));
  EXPECT_THAT(out, HasSubstr("The task is learned: 16 of 16 parts of the goal are met"));
}

// "tools go in the top drawer": WordNet has the hammer, the screwdrivers
// and the wrench as tools, so each gets the goal; the tape measure is not
// one, and is asked about in its turn.
TEST_F(Teach, AClassOfThingsGoesTogether) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/tidy-garage.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"time to tidy the garage", "clear the workbench",
                                 "tools go in the top drawer, shut it afterwards", "quit"})));
  EXPECT_EQ(teach.wait(), 1) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: tools go in the top drawer, shut it afterwards\n"
                                     "Agent: So the hammer goes in the top drawer, and the top drawer ends closed.\n"
                                     "Agent: The same goes for the screwdriver and the wrench, when I come to them.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Next, the wrench on the workbench: it goes in the top drawer"));
  EXPECT_THAT(teach.out(), HasSubstr("Agent: Where should the tape measure on the workbench go?\n"));
}

// Groceries as a person puts them: a task after a description ("I just got
// back from the store", where "back" is not the verb), "milk and cream too",
// "crackers, cereal and granola bars" (the saltines are crackers in
// WordNet), "pepper and salt", and the counter place by place.
TEST_F(Teach, AGroceryRunTaughtAsAPersonTalks) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario",
                 testing::source_path("data/scenarios/unpack-groceries.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"I just got back from the store, help me put the groceries away", "unpack the bags",
                                 "the catsup goes in the fridge and close it", "milk and cream too",
                                 "crackers, cereal and granola bars in the pantry, close it",
                                 "frozen stuff goes in the freezer, close it", "ice cream too",
                                 "soda cans in the fridge, close it", "pepper and salt on the spice shelf",
                                 "now the counter", "clear it", "throw it away", "recycle it", "same as the newspaper",
                                 "that's everything"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Agent: What should I do first to put away the groceries?\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: milk and cream too\n"
                             "Agent: So the milk goes in the fridge, and the fridge ends closed.\n"
                             "Agent: The same goes for the cream, when I come to it.\n"));
  EXPECT_THAT(out, HasSubstr("Instructor: crackers, cereal and granola bars in the pantry, close it\n"
                             "Agent: So the saltines go in the pantry, and the pantry ends closed.\n"
                             "Agent: The same goes for the cereal box and the granola bars, when I come to them.\n"));
  EXPECT_THAT(out, HasSubstr("The task is learned: 18 of 18 parts of the goal are met, after 15 instructions.\n"));
}

}  // namespace
}  // namespace apprentice
