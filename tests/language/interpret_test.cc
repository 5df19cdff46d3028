// `apprentice interpret`, through run_interpret (apps/apprentice/cmd_interpret.cc).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cmd_interpret.h"
#include "language_fixtures.h"

namespace apprentice::cli {
namespace {

using language::testing::source_path;

struct RunOutcome {
  int code;
  std::string out, err;
};

RunOutcome run(InterpretOptions options) {
  if (options.scenario.empty()) options.scenario = source_path("data/scenarios/tidy-kitchen-35.yaml").string();
  std::ostringstream out, err;
  // The exit codes main() gives these outcomes.
  CommandResult result = run_interpret(options, out);
  int code = 0;
  if (!result) {
    err << "apprentice: " << result.error().describe() << "\n";
    code = 2;
  } else if (*result == cli::Outcome::kGoalNotReached) {
    code = 1;
  }
  return {code, out.str(), err.str()};
}

InterpretOptions sentence(std::string text) {
  InterpretOptions o;
  o.sentence = std::move(text);
  return o;
}

TEST(Interpret, PrintsFormAndGrounding) {
  InterpretOptions o = sentence("the goal is that the ceramic-plate is in the dishwasher and the dishwasher is closed");
  o.object = "ceramic-plate";
  o.subtask = "unload";
  RunOutcome r = run(o);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("form: (goal (in \"ceramic-plate\" \"dishwasher\") (closed \"dishwasher\"))"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("result: goal (and (in ceramic-plate2 dishwasher1) (closed dishwasher1))"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("english: the ceramic-plate is in the dishwasher and the dishwasher is closed"),
            std::string::npos);
}

TEST(Interpret, FailuresExitOneWithAReason) {
  RunOutcome r = run(sentence("Close the recycling bin."));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("result: failure affordance-mismatch openable recycling-bin1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reason: The recycling bin has no lid, so it can't be closed."), std::string::npos) << r.out;
}

TEST(Interpret, UnparseableSentencesAndBadOptionsExitTwo) {
  EXPECT_EQ(run(sentence("the goal is for it to be tidy")).code, 2);
  InterpretOptions none;
  EXPECT_EQ(run(none).code, 2);
  InterpretOptions o = sentence("Open the fridge.");
  o.object = "no-such-thing";
  RunOutcome r = run(o);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no-such-thing"), std::string::npos);
  o = sentence("Open the fridge.");
  o.scenario = "/nonexistent.yaml";
  EXPECT_EQ(run(o).code, 2);
}

TEST(Interpret, JsonForOneSentence) {
  InterpretOptions o = sentence("the goal is that the paper-cup is in the trash can");
  o.object = "paper-cup1";
  o.json = true;
  RunOutcome r = run(o);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["result"], "goal (in paper-cup1 garbage1)");
  EXPECT_EQ(j["references"].size(), 2u);
}

TEST(Interpret, CorpusCountsOutcomesAndAgreement) {
  auto path = std::filesystem::temp_directory_path() / "apprentice_interpret_corpus.jsonl";
  {
    std::ofstream out(path);
    out << R"({"object": "plastic-bottle", "start_location": "table", "subtask": "clear", "response": "the goal is that the plastic-bottle is in the recycling bin", "stars_viable": true})" "\n";
    out << R"({"object": "plastic-bottle", "start_location": "table", "subtask": "clear", "response": "the goal is that the plastic-bottle is in the recycling bin and the recycling bin is closed", "stars_viable": false, "mismatch_type": "affordance-mismatch"})" "\n";
    out << "\n";
    out << R"({"object": "mug", "start_location": "dish rack", "subtask": "unload", "response": "the goal is that the mug is in the cabinet", "stars_viable": false, "mismatch_type": "ungrounded-object"})" "\n";
  }
  InterpretOptions o;
  o.corpus = path.string();
  RunOutcome r = run(o);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lines: 3"), std::string::npos) << r.out;
  o.json = true;
  r = run(o);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["lines"], 3);
  EXPECT_EQ(j["outcomes"]["affordance-mismatch"], 1);
  EXPECT_EQ(j["agreement"]["both_viable"], 1);
  EXPECT_EQ(j["agreement"]["both_not"], 1);
  if (language::testing::grounder().lexicon().has_wordnet()) {
    EXPECT_EQ(j["outcomes"]["goal"], 2);
    EXPECT_EQ(j["agreement"]["ours_only"], 1);
  }
  // A malformed line is bad input, named by its number.
  {
    std::ofstream out(path, std::ios::app);
    out << "{not json\n";
  }
  o.json = false;
  r = run(o);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("line 5"), std::string::npos) << r.err;
  std::filesystem::remove(path);
}

// --asked: the sentence read as a teacher's reply at that question.
TEST(Interpret, RepliesAtAQuestion) {
  InterpretOptions o = sentence("put it in the fridge and close it");
  o.asked = "goal";
  o.object = "ketchup1";
  RunOutcome r = run(o);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("meaning: goal (and (in ketchup1 fridge1) (closed fridge1))"), std::string::npos) << r.out;

  o = sentence("the milk goes in the fridge");
  o.asked = "goal";
  o.object = "ketchup1";
  r = run(o);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("reason: That says what becomes of the milk, but I asked about the ketchup on the table."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("example: "), std::string::npos) << r.out;

  o = sentence("the one on the counter");
  o.asked = "which";
  o.choices = {"mug1", "mug2"};
  r = run(o);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("meaning: chosen mug1"), std::string::npos) << r.out;

  o = sentence("yes");
  o.asked = "what";
  r = run(o);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--asked takes task"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace apprentice::cli
