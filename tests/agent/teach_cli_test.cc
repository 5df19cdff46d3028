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
using ::testing::HasSubstr;
using ::testing::Not;

const char* const kKetchupGoal =
    "If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.";
const char* const kPaperPlateGoal = "If the object is a paper-plate then the goal is that the object is in the garbage.";

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

  Knowledge stored() const {
    Scenario scenario = testing::load_or_die(scenario_);
    auto store = KnowledgeStore::open(knowledge());
    EXPECT_TRUE(store.has_value()) << (store ? "" : store.error().describe());
    if (!store) return {};
    auto loaded = store->load(*scenario.world.domain);
    EXPECT_TRUE(loaded.has_value()) << (loaded ? "" : loaded.error().describe());
    return loaded ? std::move(*loaded) : Knowledge{};
  }

  fs::path scenario_ = testing::source_path("tests/agent/data/two-objects.yaml");
};

TEST_F(Teach, LearnsTheTaskFromAScriptOnStdin) {
  Process teach(teach_args());
  ASSERT_TRUE(teach.started());
  std::string script;
  for (const std::string& line : full_script()) script += line + "\n";
  ASSERT_TRUE(teach.write(script));
  int code = teach.wait();
  EXPECT_EQ(code, 0) << teach.out() << teach.err();
  EXPECT_EQ(teach.out(),
            "Teaching in two-objects (inst+search4). Type 'status' to see the world, Ctrl-D to stop.\n"
            "Agent: What task should I learn?\n"
            "Instructor: Tidy kitchen.\n"
            "Agent: What is the next goal or subtask of tidy?\n"
            "Instructor: Repeat the following tasks while an object is on the table.\n"
            "Agent: What is the next goal or subtask of tidy?\n"
            "Instructor: Clear an object that is on the table.\n"
            "Agent: What is the next goal or subtask of clear?\n"
            "Instructor: " + std::string(kKetchupGoal) + "\n"
            "Agent: What is the next goal or subtask of clear?\n"
            "Instructor: You are done.\n"
            "Agent: What is the next goal or subtask of tidy?\n"
            "Instructor: Repeat.\n"
            "Agent: What is the next goal or subtask of clear?\n"
            "Instructor: " + std::string(kPaperPlateGoal) + "\n"
            "Agent: What is the next goal or subtask of tidy?\n"
            "Instructor: You are done.\n"
            "The task is learned. 3 of 3 goal assertions hold; 8 instructions. Knowledge is in " +
                knowledge().string() + ".\n");
  Knowledge knowledge = stored();
  EXPECT_EQ(knowledge.goals.size(), 2u);
  ASSERT_EQ(knowledge.tasks.size(), 1u);
  EXPECT_EQ(knowledge.tasks[0].name, "tidy kitchen");
}

TEST_F(Teach, TheInstructorTeachesActionsWithoutSearch) {
  Process teach(teach_args("instruction"));
  std::vector<std::string> script = {"Tidy kitchen.",
                                     "Repeat the following tasks while an object is on the table.",
                                     "Clear an object that is on the table.",
                                     kKetchupGoal,
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
  for (const std::string& line : script) ASSERT_TRUE(teach.write(line + "\n"));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: What do I do next for clear?\nInstructor: Open the fridge.\n"));
  EXPECT_THAT(teach.out(), HasSubstr("The task is learned. 3 of 3 goal assertions hold; 14 instructions."));
}

TEST_F(Teach, StatusShowsTheWorldAndIsNotAnInstruction) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  script.insert(script.begin() + 3, "status");
  for (const std::string& line : script) ASSERT_TRUE(teach.write(line + "\n"));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: status\nWorld (kitchen):\n  fridge1 is closed\n"
                                     "  on table1: ketchup1 paper-plate1\n"));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 goal assertions hold; 8 instructions."));
}

TEST_F(Teach, CtrlDMidWayStopsCleanlyAndKeepsTheGoalsGivenSoFar) {
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
  ASSERT_TRUE(teach.read_until(kKetchupGoal)) << teach.out() << teach.err();
  ASSERT_TRUE(teach.read_until("Agent: What is the next goal or subtask of clear?\nInstructor: ",
                               teach.out().find(kKetchupGoal)))
      << teach.out() << teach.err();
  teach.close_stdin();
  int code = teach.wait();
  EXPECT_EQ(code, 1) << "the goal was not reached: " << teach.out() << teach.err();
  // A clean message on its own line, no error.
  EXPECT_THAT(teach.out(),
              ::testing::EndsWith("Agent: What is the next goal or subtask of clear?\nInstructor: \n"
                                  "Stopped. 2 of 3 goal assertions hold; 4 instructions. Knowledge is in " +
                                  knowledge().string() + ".\n"));
  EXPECT_THAT(teach.err(), Not(HasSubstr("rror")));
  // The ketchup's goal and the task's structure were kept.
  Knowledge knowledge = stored();
  ASSERT_EQ(knowledge.goals.size(), 1u);
  EXPECT_EQ(knowledge.goals.all()[0].key.category, "ketchup");
  ASSERT_EQ(knowledge.tasks.size(), 1u);
  EXPECT_EQ(knowledge.tasks[0].subtasks.size(), 1u);

  // Teaching again with that knowledge: the agent does not ask for the
  // ketchup's goal again.
  Process again(teach_args());
  std::vector<std::string> rest = {script[0], script[1], script[2], "You are done.", "Repeat.", kPaperPlateGoal,
                                   "You are done."};
  for (const std::string& line : rest) ASSERT_TRUE(again.write(line + "\n"));
  EXPECT_EQ(again.wait(), 0) << again.out() << again.err();
  EXPECT_THAT(again.out(), HasSubstr("The task is learned. 3 of 3 goal assertions hold; 7 instructions."));
  EXPECT_THAT(again.out(), Not(HasSubstr(kKetchupGoal)));
  EXPECT_EQ(stored().goals.size(), 2u);
}

TEST_F(Teach, EndOfInputBeforeAnythingIsStillClean) {
  // Only the fridge's door holds already (it starts closed).
  Process teach(teach_args());
  EXPECT_EQ(teach.wait(), 1);
  EXPECT_THAT(teach.out(), ::testing::EndsWith("Instructor: \nStopped. 1 of 3 goal assertions hold; 0 instructions. "
                                               "Knowledge is in " + knowledge().string() + ".\n"));
}

TEST_F(Teach, RepliesTheAgentCannotUseAreSaidSo) {
  Process teach(teach_args());
  std::vector<std::string> script = full_script();
  script.insert(script.begin() + 3, "If the object is a ketchup then the goal is that the object is in the moon.");
  for (const std::string& line : script) ASSERT_TRUE(teach.write(line + "\n"));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  // The agent said why and asked again; the unusable reply still counts.
  EXPECT_THAT(teach.out(), HasSubstr("in the moon.\nAgent: "));
  EXPECT_THAT(teach.out(), HasSubstr("3 of 3 goal assertions hold; 9 instructions."));
}

}  // namespace
}  // namespace apprentice
