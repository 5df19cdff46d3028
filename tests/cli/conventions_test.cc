// Command-line conventions (issue 11), tried as a new user would, against
// git's and ripgrep's: every error starts "apprentice:", names the flag or
// word at fault, suggests the near miss, and exits 2.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"

namespace apprentice {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using testing::Invocation;

namespace fs = std::filesystem;

class Conventions : public testing::ScratchTest {
 protected:
  Invocation run(const std::vector<std::string>& args) const { return testing::run_cli(args, dir_, fs::path()); }
  std::string kitchen() const { return testing::scenario_path("tidy-kitchen").string(); }
};

TEST_F(Conventions, AnUnknownCommandIsNamedWithWhereToLook) {
  Invocation r = run({"frobnicate"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("apprentice: 'frobnicate' is not a command. See 'apprentice --help'.\n"));
  EXPECT_THAT(r.err, Not(HasSubstr("most similar")));
}

TEST_F(Conventions, ANearMissSuggestsTheCommand) {
  Invocation r = run({"tech", "--scenario", kitchen()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("'tech' is not a command"));
  EXPECT_THAT(r.err, HasSubstr("The most similar command is\n\tteach\n"));
}

TEST_F(Conventions, HelpAsACommandPrintsHelp) {
  Invocation all = run({"help"});
  EXPECT_EQ(all.exit_code, 0);
  EXPECT_THAT(all.out, AllOf(HasSubstr("Usage: apprentice"), HasSubstr("teach"), HasSubstr("experiment")));
  Invocation teach = run({"help", "teach"});
  EXPECT_EQ(teach.exit_code, 0);
  EXPECT_THAT(teach.out, AllOf(HasSubstr("Teach the agent"), HasSubstr("--knowledge")));
  Invocation bad = run({"help", "frob"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("'frob' is not a command"));
}

TEST_F(Conventions, AnUnknownFlagIsReportedBeforeAMissingOne) {
  Invocation r = run({"teach", "--frob"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "apprentice: teach: unknown option \"--frob\". See 'apprentice help teach'.\n");
  Invocation missing = run({"teach"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err,
            "apprentice: teach: no world given: name a scenario file, as in 'apprentice teach FILE' or "
            "'--scenario FILE'. See 'apprentice help teach'.\n");
}

// What a newcomer types first, `apprentice teach kitchen.yaml`, works as
// --scenario does, in every command that works in one world.
TEST_F(Conventions, TheWorldMayBeGivenWithoutScenario) {
  for (const std::string command : {"world", "plan", "export-pddl", "experiment", "run"}) {
    std::vector<std::string> flagged{command, "--scenario", kitchen(), "--frob"};
    std::vector<std::string> bare{command, kitchen(), "--frob"};
    // Both forms reach the same check of the rest of the line.
    EXPECT_EQ(run(flagged).err, run(bare).err) << command;
  }
  Invocation flagged = run({"world", "--scenario", kitchen(), "--json"});
  Invocation bare = run({"world", kitchen(), "--json"});
  EXPECT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_EQ(bare.out, flagged.out);
  EXPECT_THAT(bare.out, HasSubstr("\"fridge1\""));
  Invocation plan = run({"plan", kitchen(), "--goal", "(closed fridge1)"});
  EXPECT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_THAT(plan.out, StartsWith("Greedy best-first search found in "));
  EXPECT_THAT(plan.out, HasSubstr(" ms that the goal holds already, so no step is needed: "));
  Invocation twice = run({"world", kitchen(), "--scenario", kitchen()});
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_THAT(twice.err, HasSubstr("the world is already given by --scenario"));
  Invocation two = run({"world", kitchen(), kitchen()});
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_THAT(two.err, HasSubstr("unexpected argument"));
}

TEST_F(Conventions, AMistypedFlagGetsTheNearestOne) {
  Invocation r = run({"world", "--scenrio", kitchen()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "apprentice: world: --scenrio: did you mean --scenario? See 'apprentice help world'.\n");
  Invocation equals = run({"experiment", "--scenario", kitchen(), "--conditons=instruction"});
  EXPECT_EQ(equals.exit_code, 2);
  EXPECT_THAT(equals.err, HasSubstr("--conditons: did you mean --conditions?"));
  // Another word for the knowledge store, as two fresh users typed it.
  Invocation store = run({"teach", "--scenario", kitchen(), "--store", "x.sqlite"});
  EXPECT_EQ(store.exit_code, 2);
  EXPECT_THAT(store.err, HasSubstr("--store: did you mean --knowledge (the knowledge store)?"));
  // A word that is not a flag is still an unexpected argument.
  Invocation extra = run({"world", "--scenario", kitchen(), "extra"});
  EXPECT_EQ(extra.exit_code, 2);
  EXPECT_THAT(extra.err, HasSubstr("unexpected argument \"extra\""));
}

TEST_F(Conventions, ANumberThatIsNotANumberSaysSo) {
  Invocation r = run({"plan", "--scenario", kitchen(), "--goal", "(closed fridge1)", "--depth", "abc"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("apprentice: plan: --depth: 'abc' is not a whole number"));
  Invocation range = run({"plan", "--scenario", kitchen(), "--goal", "(closed fridge1)", "--depth", "99"});
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_THAT(range.err, HasSubstr("--depth: '99' is out of range (0 to 64)"));
  Invocation seconds = run({"plan", "--scenario", kitchen(), "--goal", "(closed fridge1)", "--time-limit", "soon"});
  EXPECT_EQ(seconds.exit_code, 2);
  EXPECT_THAT(seconds.err, HasSubstr("--time-limit: 'soon' is not a number"));
}

TEST_F(Conventions, AGoalInEnglishIsToldWhatAGoalIs) {
  Invocation r = run({"plan", "--scenario", kitchen(), "--goal", "put the ketchup in the fridge"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, AllOf(HasSubstr("is not a goal"), HasSubstr("(in ketchup1 fridge1)"), HasSubstr("interpret")));
}

TEST_F(Conventions, AnObjectWithoutItsNumberIsSuggested) {
  Invocation r = run({"plan", "--scenario", kitchen(), "--goal", "(in ketchup fridge1)"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("there is no ketchup; did you mean ketchup1?"));
}

TEST_F(Conventions, SpacesAfterCommasInConditionsAreTolerated) {
  Invocation r = run({"experiment", "--scenario", kitchen(), "--conditions", "instruction, inst+search4", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, AllOf(HasSubstr("\"instruction\""), HasSubstr("\"inst+search4\"")));
}

TEST_F(Conventions, ABadLlmSpecIsBlamedOnTheFlag) {
  Invocation r = run({"experiment", "--scenario", kitchen(), "--conditions", "inst+llm", "--llm", "bogus"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("apprentice: experiment: --llm: \"bogus\" is not an LLM backend"));
  EXPECT_THAT(r.err, Not(HasSubstr("condition")));
}

TEST_F(Conventions, VerboseAndQuietAreAcceptedAfterEverySubcommand) {
  for (const char* flag : {"-v", "--verbose", "-q", "--quiet"}) {
    Invocation r = run({"world", "--scenario", kitchen(), flag});
    EXPECT_EQ(r.exit_code, 0) << flag << ": " << r.err;
  }
  Invocation verbose = run({"plan", "--scenario", kitchen(), "--goal", "(closed fridge1)", "-v"});
  EXPECT_EQ(verbose.exit_code, 0) << verbose.err;
  EXPECT_THAT(verbose.err, HasSubstr("[info]"));
}

TEST_F(Conventions, RunNamesTheStoreAndTheTasksItHolds) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(run({"experiment", "--scenario", kitchen(), "--conditions", "instruction", "-q", "--knowledge-out",
                 out.string()})
                .exit_code,
            0);
  const std::string store = (out / "instruction.sqlite").string();
  Invocation r = run({"run", "--scenario", kitchen(), "--knowledge", store, "--task", "clean house"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(store));
  EXPECT_THAT(r.err, HasSubstr("no task \"clean house\" has been learned"));
  EXPECT_THAT(r.err, HasSubstr("holds 1 task: \"tidy kitchen\""));
}

TEST_F(Conventions, APlanThatCannotBeFoundSaysWhatToTry) {
  Invocation conflict = run({"plan", "--scenario", kitchen(), "--goal", "(and (holding ketchup1) (handempty))"});
  EXPECT_EQ(conflict.exit_code, 1);
  EXPECT_THAT(conflict.err, HasSubstr("apprentice: no sequence of actions reaches the goal from this state"));
  EXPECT_THAT(conflict.err, HasSubstr("its parts cannot all hold at once"));
  Invocation shallow = run({"plan", "--scenario", kitchen(), "--goal", "(in ketchup1 fridge1)", "--depth", "1"});
  EXPECT_EQ(shallow.exit_code, 1);
  EXPECT_THAT(shallow.err, HasSubstr("try a larger --depth"));
}

TEST_F(Conventions, AGoalThatCanNeverHoldSaysWhyInEnglish) {
  // Closing a lidless bin: with greedy search, and with --depth (where more
  // depth would not help, so none is suggested).
  for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"--depth", "2"}}) {
    std::vector<std::string> args{"plan", "--scenario", kitchen(), "--goal", "(closed recycling-bin1)"};
    args.insert(args.end(), extra.begin(), extra.end());
    Invocation lidless = run(args);
    EXPECT_EQ(lidless.exit_code, 1);
    EXPECT_THAT(lidless.err,
                HasSubstr("apprentice: The recycling bin will never be closed: it has no door, so I cannot close it.\n"));
    EXPECT_THAT(lidless.err, Not(HasSubstr("--depth")));
    EXPECT_THAT(lidless.err, Not(HasSubstr("(openable")));
  }
  Invocation json = run({"plan", "--scenario", kitchen(), "--goal", "(and (in ketchup1 fridge1) (not (grabbable ketchup1)))",
                         "--json"});
  EXPECT_EQ(json.exit_code, 1);
  auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["status"], "exhausted");
  EXPECT_EQ(j["never_holds"], "The ketchup will never stop being something I can pick up: nothing I can do undoes that.");
}

TEST_F(Conventions, EveryErrorHasThePrefix) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"world"}, {"world", "--scenario"}, {"plan", "--depth", "x"}, {"frob"},
        {"world", "--scenario", kitchen(), "extra"}}) {
    Invocation r = run(args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_THAT(r.err, StartsWith("apprentice: ")) << testing::shell_quote(args.empty() ? "" : args[0]);
  }
}

}  // namespace
}  // namespace apprentice
