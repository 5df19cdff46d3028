// `apprentice experiment` as a user runs it: --json prints one object per
// condition with the documented keys and types, and --transcript writes
// each condition's dialogue, as the paper prints dialogues, to its own file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiment_fixtures.h"
#include "fake_llm_server.h"

namespace apprentice {
namespace {

using nlohmann::json;
using testing::source_path;
using ::testing::ElementsAreArray;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::vector<std::string> kKeys = {"assertions_achieved", "assertions_total", "completion_rate",
                                        "condition",           "degraded",         "degraded_why",
                                        "instructions",        "llm_calls",        "llm_ensemble",
                                        "llm_failures",        "llm_stop_error",   "llm_stopped",
                                        "llm_stopped_after_calls", "llm_tokens",   "objects_done",
                                        "objects_total",       "relevance",        "search_nodes",
                                        "transfer",            "wall_ms",          "words",
                                        "yes_no"};

std::vector<std::string> keys_of(const json& object) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : object.items()) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  return keys;
}

void expect_types(const json& r, bool llm) {
  EXPECT_TRUE(r["condition"].is_string());
  EXPECT_TRUE(r["completion_rate"].is_number());
  EXPECT_TRUE(r["llm_ensemble"].is_boolean());
  EXPECT_EQ(r["degraded"], false);  // a healthy run
  EXPECT_TRUE(r["degraded_why"].is_null());
  EXPECT_EQ(r["llm_stopped"], false);
  for (const char* key : {"assertions_achieved", "assertions_total", "objects_done", "objects_total", "instructions",
                          "words", "yes_no", "llm_calls", "llm_tokens", "llm_failures", "search_nodes"}) {
    EXPECT_TRUE(r[key].is_number_integer()) << key << " is " << r[key].dump();
    EXPECT_GE(r[key].get<long>(), 0) << key;
  }
  EXPECT_TRUE(r["wall_ms"].is_number());
  EXPECT_GE(r["wall_ms"].get<double>(), 0.0);
  if (llm) {
    EXPECT_TRUE(r["relevance"].is_number()) << r["relevance"].dump();
  } else {
    EXPECT_TRUE(r["relevance"].is_null()) << "the paper's -- is null: " << r["relevance"].dump();
  }
}

// Every line is "Agent: ..." or "Instructor: ...", and the instructor
// speaks only in answer to the agent.
void expect_paper_dialogue(const std::string& transcript) {
  EXPECT_THAT(transcript, StartsWith("Agent: What task should I learn?\nInstructor: Tidy kitchen.\n"));
  EXPECT_THAT(transcript, ::testing::EndsWith("\n"));
  std::istringstream in(transcript);
  std::string previous;
  int lines = 0;
  for (std::string line; std::getline(in, line); ++lines) {
    bool agent = line.rfind("Agent: ", 0) == 0, instructor = line.rfind("Instructor: ", 0) == 0;
    EXPECT_TRUE(agent || instructor) << line;
    if (instructor) {
      EXPECT_EQ(previous.rfind("Agent: ", 0), 0u) << "unprompted: " << line;
    }
    previous = line;
  }
  EXPECT_GT(lines, 2);
}

class ExperimentCli : public testing::ScratchTest {};

TEST_F(ExperimentCli, JsonHasOneObjectPerConditionWithTheDocumentedKeys) {
  testing::Invocation run = testing::run_cli({"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml",
                                              "--conditions", "instruction,inst+search4", "--json", "--transcript",
                                              (dir_ / "t").string()},
                                             dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  json all = json::parse(run.out);
  ASSERT_TRUE(all.is_array());
  ASSERT_EQ(all.size(), 2u);
  for (const json& r : all) {
    EXPECT_THAT(keys_of(r), ElementsAreArray(kKeys));
    expect_types(r, false);
  }
  EXPECT_EQ(all[0]["condition"], "instruction");
  EXPECT_EQ(all[1]["condition"], "inst+search4");
  // Issue 4's figures.
  EXPECT_EQ(all[0]["completion_rate"].get<double>(), 100.0);
  EXPECT_EQ(all[1]["completion_rate"].get<double>(), 100.0);
  EXPECT_EQ(all[1]["instructions"], 40);
  EXPECT_EQ(all[1]["words"], 603);
  EXPECT_EQ(all[1]["yes_no"], 0);
  EXPECT_EQ(all[1]["assertions_achieved"], 35);
  EXPECT_EQ(all[1]["assertions_total"], 35);
  EXPECT_EQ(all[1]["objects_done"], 30);
  EXPECT_EQ(all[1]["objects_total"], 30);
  EXPECT_EQ(all[0]["yes_no"], 0);
  EXPECT_EQ(all[0]["search_nodes"], 0);
  EXPECT_GT(all[1]["search_nodes"].get<long>(), 0);
  EXPECT_EQ(all[1]["llm_calls"], 0);
  std::printf("instruction: %s\ninst+search4: %s\n", all[0].dump().c_str(), all[1].dump().c_str());
}

TEST_F(ExperimentCli, JsonOfLlmConditionsHasRelevanceAndLlmUsage) {
  testing::FakeLlmServer server(testing::ServerMode::kModel,
                                {{"ketchup", {"The goal is that the X is in the fridge and the fridge is closed"}}});
  testing::Invocation run = testing::run_cli(
      {"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "inst+search4+llm,search4+llm",
       "--json", "--llm", "openai:" + server.url()},
      dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  json all = json::parse(run.out);
  ASSERT_EQ(all.size(), 2u);
  for (const json& r : all) {
    EXPECT_THAT(keys_of(r), ElementsAreArray(kKeys));
    expect_types(r, true);
    EXPECT_GT(r["llm_calls"].get<int>(), 0);
    EXPECT_GT(r["llm_tokens"].get<long>(), 0);
  }
  EXPECT_EQ(all[0]["completion_rate"].get<double>(), 100.0);
}

TEST_F(ExperimentCli, EachConditionsTranscriptIsItsOwnFileAsThePaperPrintsDialogues) {
  const auto dir = dir_ / "transcripts";
  testing::Invocation run = testing::run_cli({"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml",
                                              "--conditions", "instruction,inst+search4", "--transcript",
                                              dir.string()},
                                             dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  Scenario scenario = testing::load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  for (const std::string name : {"instruction", "inst+search4"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(std::filesystem::exists(dir / (name + ".txt")));
    const std::string transcript = testing::read_text(dir / (name + ".txt"));
    expect_paper_dialogue(transcript);
    // The file is the run's dialogue: the same as a run in this process.
    EXPECT_EQ(transcript, testing::run(scenario, name, testing::experiment_options()).transcript);
  }
  EXPECT_THAT(testing::read_text(dir / "instruction.txt"),
              HasSubstr("Agent: What should I do next so that the ceramic plate is in the dishwasher and the "
                        "dishwasher is closed?\nInstructor: Open the dishwasher.\n"));
  // The human-readable table compares with the paper.
  EXPECT_THAT(run.out, HasSubstr("inst+search4       ours         100.0     30/30        --       40     603       0"));
  EXPECT_THAT(run.out, HasSubstr("                   paper        100.0                  --       40     603       0"));
  EXPECT_THAT(run.out, HasSubstr("the floor (task structure and one goal per goal type) is 40 instructions, 603 words"));
}

TEST_F(ExperimentCli, ThePapersRowsAppearOnlyBesideThePapersKitchen) {
  testing::Invocation run = testing::run_cli(
      {"experiment", "--scenario", "data/scenarios/tidy-kitchen-35.yaml", "--conditions", "inst+search4"}, dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("inst+search4       ours         100.0     35/35"));
  // No "paper" row (the legend below the table may mention the paper).
  EXPECT_THAT(run.out, ::testing::Not(::testing::ContainsRegex("\n +paper +[0-9]")));
}

// A scenario without an intent: a world to look at, plan in and teach in,
// but nothing the simulated instructor could teach or completion be
// measured against.
TEST_F(ExperimentCli, WithoutAnIntentTheExperimentSaysWhatIsMissing) {
  std::string text = testing::read_text(source_path("data/scenarios/tidy-kitchen.yaml"));
  text = text.substr(0, text.find("# What the instructor wants."));
  text.replace(text.find("domain: ../domains/kitchen.pddl"), 31, "domain: " + source_path("data/domains/kitchen.pddl").string());
  const auto path = dir_ / "no-intent.yaml";
  std::ofstream(path) << text;
  testing::Invocation run = testing::run_cli({"experiment", "--scenario", path.string()}, dir_);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("no-intent.yaml: the experiment needs a scenario with a task and an intent"));
  EXPECT_THAT(run.err, HasSubstr("this one has no intent"));
  EXPECT_EQ(run.out, "");
  for (std::vector<std::string> args :
       {std::vector<std::string>{"world", "--scenario", path.string()},
        std::vector<std::string>{"plan", "--scenario", path.string(), "--goal", "(in ketchup1 fridge1)"},
        std::vector<std::string>{"export-pddl", "--scenario", path.string(), "--goal", "(in ketchup1 fridge1)",
                                 "--out", (dir_ / "pddl").string()}}) {
    testing::Invocation ok = testing::run_cli(args, dir_);
    EXPECT_EQ(ok.exit_code, 0) << args[0] << ": " << ok.err;
  }
}

TEST_F(ExperimentCli, AnLlmConditionWithoutAnLlmIsAnError) {
  testing::Invocation run = testing::run_cli(
      {"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "inst+llm"}, dir_);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_THAT(run.err, HasSubstr("--llm"));
}

TEST_F(ExperimentCli, AnUnknownConditionIsAnError) {
  testing::Invocation run = testing::run_cli(
      {"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "inst+telepathy"}, dir_);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_THAT(run.err, HasSubstr("telepathy"));
}

}  // namespace
}  // namespace apprentice
