// End to end: learn tidy-kitchen.yaml with the real binary
// (`apprentice experiment --knowledge-out`), then perform it, and the
// similar kitchen, from the store alone (`apprentice run`): 100%
// completion with no instruction, no search and no LLM. And the
// instruction condition's figures against the paper's Table 3 row.
#include <map>
#include <memory>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "agent/agent.h"
#include "experiment/experiment.h"
#include "knowledge/store.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using namespace apprentice::testing;

struct Learned {
  std::unique_ptr<ScratchDir> dir;
  fs::path store;
  nlohmann::json result;  // the experiment's JSON for the condition
  int exit_code = -1;
  std::string err;
};

// Learning runs once per (condition, generalization) for the whole binary.
Learned& learned(const std::string& condition, const std::string& generalization) {
  static std::map<std::string, Learned> cache;
  std::string key = condition + "/" + generalization;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Learned l;
  l.dir = std::make_unique<ScratchDir>(/*in_memory=*/true);
  Invocation r = run_cli(l.dir->path(), {"experiment", "--scenario", scenario_path("tidy-kitchen").string(),
                                          "--conditions", condition, "--generalization", generalization,
                                          "--knowledge-out", (l.dir->path() / "out").string(), "--json"});
  l.exit_code = r.exit_code;
  l.err = r.err;
  l.store = l.dir->path() / "out" / (condition + ".sqlite");
  auto all = nlohmann::json::parse(r.out, nullptr, false);
  if (!all.is_discarded() && all.is_array() && all.size() == 1) l.result = all[0];
  return cache.emplace(key, std::move(l)).first->second;
}

struct Case {
  const char* condition;
  const char* generalization;
  const char* scenario;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.condition << " --generalization " << c.generalization << ", run on " << c.scenario;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::string(info.param.condition) + "_" + info.param.generalization + "_" + info.param.scenario;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class OneShot : public ::testing::TestWithParam<Case> {};

TEST_P(OneShot, LearningCompletesTheTask) {
  const Case& c = GetParam();
  Learned& l = learned(c.condition, c.generalization);
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ASSERT_TRUE(l.result.is_object()) << l.err;
  EXPECT_EQ(l.result["completion_rate"], 100.0);
  EXPECT_EQ(l.result["llm_calls"], 0);
  EXPECT_TRUE(fs::exists(l.store));
}

TEST_P(OneShot, RunWithTheStoreAloneCompletesWithNoHelp) {
  const Case& c = GetParam();
  Learned& l = learned(c.condition, c.generalization);
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ScratchDir dir;
  Invocation r = run_cli(dir.path(), {"run", "--scenario", scenario_path(c.scenario).string(), "--knowledge",
                                      l.store.string(), "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out << r.err;
  EXPECT_EQ(json["completion_rate"], 100.0);
  EXPECT_EQ(json["assertions_achieved"], json["assertions_total"]);
  EXPECT_EQ(json["instructions"], 0);
  EXPECT_EQ(json["search_nodes"], 0);
  EXPECT_EQ(json["llm_calls"], 0);
  EXPECT_EQ(json["help_needed"], nlohmann::json::array());
  EXPECT_GT(json["actions"].get<int>(), 0);
}

TEST_P(OneShot, EveryActionComesFromALearnedRuleAndEveryGoalFromMemory) {
  // The same, through the library, so that the report can show where each
  // action and goal came from.
  const Case& c = GetParam();
  Learned& l = learned(c.condition, c.generalization);
  ASSERT_EQ(l.exit_code, 0) << l.err;
  Scenario scenario = load_or_die(scenario_path(c.scenario));
  auto store = KnowledgeStore::open(l.store);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  auto knowledge = store->load(*scenario.world.domain);
  ASSERT_TRUE(knowledge.has_value()) << knowledge.error().describe();
  AgentOptions options;
  options.condition = Condition{"knowledge-only", false, 0, false};
  TaskLearningAgent agent(options, std::move(*knowledge), Understanding(), nullptr, nullptr);
  Simulator simulator(scenario.world);
  auto report = agent.perform(simulator, "tidy kitchen");
  ASSERT_TRUE(report.has_value()) << report.error().describe();
  EXPECT_TRUE(report->help_needed.empty()) << ::testing::PrintToString(report->help_needed);
  EXPECT_EQ(report->search_nodes, 0u);
  EXPECT_EQ(report->searches, 0);
  EXPECT_GT(report->actions_executed, 0);
  EXPECT_EQ(report->rule_actions, report->actions_executed);
  EXPECT_EQ(report->goals_learned, 0);
  EXPECT_EQ(report->rules_learned, 0);
  for (const ObjectReport& o : report->objects) {
    EXPECT_TRUE(o.achieved) << o.object << ": " << o.note;
    EXPECT_EQ(o.goal_source, GoalSource::kMemory) << o.object;
  }
  EXPECT_EQ(count_achieved_assertions(scenario, simulator.state()),
            static_cast<int>(scenario.goal_assertions().size()));
}

INSTANTIATE_TEST_SUITE_P(Conditions, OneShot,
                         ::testing::Values(Case{"instruction", "full", "tidy-kitchen"},
                                           Case{"instruction", "full", "tidy-kitchen-similar"},
                                           Case{"instruction", "paper", "tidy-kitchen"},
                                           Case{"instruction", "paper", "tidy-kitchen-similar"},
                                           Case{"inst+search4", "full", "tidy-kitchen"},
                                           Case{"inst+search4", "full", "tidy-kitchen-similar"},
                                           Case{"inst+search4", "paper", "tidy-kitchen"},
                                           Case{"inst+search4", "paper", "tidy-kitchen-similar"}),
                         case_name);

TEST(OneShotLimits, NewKindsOfObjectsNeedHelpAndExitOne) {
  // tidy-kitchen-35.yaml has categories never taught: the store has no goal
  // for them, and `run` says so instead of guessing.
  Learned& l = learned("instruction", "full");
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ScratchDir dir;
  Invocation r = run_cli(dir.path(), {"run", "--scenario", scenario_path("tidy-kitchen-35").string(), "--knowledge",
                                      l.store.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("Would need help: where the "));
  EXPECT_THAT(r.out, HasSubstr("0 instructions, 0 search nodes, 0 LLM calls"));
}

// The paper's Table 3 row for the instruction condition: 100% completion
// with 76 instructions and 757 words. Ours must not need more.
TEST(InstructionCondition, CompletesWithinThePapersInstructionsAndWords) {
  for (const char* generalization : {"paper", "full"}) {
    Learned& l = learned("instruction", generalization);
    ASSERT_EQ(l.exit_code, 0) << l.err;
    EXPECT_EQ(l.result["completion_rate"], 100.0) << generalization;
    EXPECT_LE(l.result["instructions"].get<int>(), 76) << generalization;
    EXPECT_LE(l.result["words"].get<int>(), 757) << generalization;
    EXPECT_EQ(l.result["yes_no"], 0) << generalization;
    EXPECT_EQ(l.result["search_nodes"], 0) << generalization;
  }
}

// The exact figures today, so that any change shows. With kPaper rules the
// agent needs exactly the paper's 76 instructions and 757 words: 14 about
// the task structure, 26 goal descriptions and 36 action commands (a new
// open/put-in/close, or pick-up, rule per subtask and receptacle or
// surface). kFull rules need only 8 action commands (the ceramic plate's
// 4, the paper plate's 2 for a goal without a door, and the ceramic bowl's
// 2 to open a receptacle and take an item out of one), so 48 instructions
// and 636 words. If learning improves, lower these after checking the
// transcript (`apprentice experiment --transcript DIR`).
TEST(InstructionCondition, CurrentFiguresRegression) {
  Learned& paper = learned("instruction", "paper");
  ASSERT_EQ(paper.exit_code, 0) << paper.err;
  EXPECT_EQ(paper.result["instructions"], 76);
  EXPECT_EQ(paper.result["words"], 757);
  Learned& full = learned("instruction", "full");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_EQ(full.result["instructions"], 48);
  EXPECT_EQ(full.result["words"], 636);
}

// The inst+search4 row: 40 instructions and 603 words in the paper. Search
// finds every action, so only the task structure and goals are taught,
// whatever the generalization.
TEST(InstSearch4Condition, CurrentFiguresRegression) {
  for (const char* generalization : {"paper", "full"}) {
    Learned& l = learned("inst+search4", generalization);
    ASSERT_EQ(l.exit_code, 0) << l.err;
    EXPECT_EQ(l.result["completion_rate"], 100.0) << generalization;
    EXPECT_EQ(l.result["instructions"], 40) << generalization;
    EXPECT_EQ(l.result["words"], 603) << generalization;
    EXPECT_GT(l.result["search_nodes"].get<int>(), 0) << generalization;
  }
}

TEST(InstSearch4Condition, FullRulesSaveSearch) {
  // Rules learned from one search serve later objects, so kFull expands
  // fewer nodes than kPaper, whose rules transfer less.
  Learned& paper = learned("inst+search4", "paper");
  Learned& full = learned("inst+search4", "full");
  ASSERT_EQ(paper.exit_code, 0);
  ASSERT_EQ(full.exit_code, 0);
  EXPECT_LT(full.result["search_nodes"].get<int>(), paper.result["search_nodes"].get<int>());
}

TEST(KnowledgeCommand, PrintsTheCeramicPlatesRulesAsLearned) {
  Learned& l = learned("instruction", "full");
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ScratchDir dir;
  Invocation r = run_cli(dir.path(), {"knowledge", "--knowledge", l.store.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  EXPECT_EQ(json["goals"].size(), 26u);
  ASSERT_EQ(json["rules"].size(), 8u);
  // The first four are the golden file's, learned on the ceramic plate.
  std::vector<std::string> golden;
  std::istringstream in(read_text(fs::path(APPRENTICE_GOLDEN_DIR) / "ceramic_plate_full.rules"));
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') golden.push_back(line);
  ASSERT_EQ(golden.size(), 4u);
  for (std::size_t i = 0; i < golden.size(); ++i) {
    EXPECT_EQ(json["rules"][i]["signature"], golden[i]);
    EXPECT_EQ(json["rules"][i]["object"], "ceramic-plate1 (ceramic-plate)");
    EXPECT_THAT(json["rules"][i]["source"].get<std::string>(), HasSubstr("instructor: "));
  }
}

// Found by a fresh user: `knowledge` listed every guess the examples
// induce, down to "placental goes on the bed" at 11%. In English it lists
// the rules at least even odds sure, says how many weaker guesses it left
// out, and lists them all with --all; --json always has all.
TEST(KnowledgeCommand, WeakerGuessesAreCountedAndListedWithAll) {
  Learned& l = learned("inst+search4", "full");
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ScratchDir dir;
  Invocation json = run_cli(dir.path(), {"knowledge", "--knowledge", l.store.string(), "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json rules = nlohmann::json::parse(json.out, nullptr, false)["class_rules"];
  std::vector<std::string> weak, strong;
  for (const nlohmann::json& rule : rules)
    (rule["source"] == "induced" && rule["confidence"].get<double>() < 0.5 ? weak : strong).push_back(rule["text"]);
  ASSERT_FALSE(weak.empty()) << "the kitchen's examples induce weaker guesses too";
  ASSERT_FALSE(strong.empty());
  Invocation plain = run_cli(dir.path(), {"knowledge", "--knowledge", l.store.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  for (const std::string& text : strong) EXPECT_THAT(plain.out, HasSubstr("  " + text + "\n"));
  for (const std::string& text : weak) EXPECT_THAT(plain.out, Not(HasSubstr("  " + text + "\n")));
  EXPECT_THAT(plain.out, HasSubstr("(and " + std::to_string(weak.size()) + " weaker guess"));
  EXPECT_THAT(plain.out, HasSubstr("--all lists them)"));
  Invocation all = run_cli(dir.path(), {"knowledge", "--knowledge", l.store.string(), "--all"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  for (const std::string& text : weak) EXPECT_THAT(all.out, HasSubstr("  " + text + "\n"));
  EXPECT_THAT(all.out, Not(HasSubstr("weaker guess")));
}

// `knowledge` lists the class rules with their evidence and source, and
// `knowledge forget` forgets one for good: it is no longer listed among
// those in use after a reload (though the goals still induce it), and is
// listed as forgotten. A phrase that names no rule, or several, is exit 2.
TEST(KnowledgeCommand, ForgetsAClassRuleForGood) {
  Learned& l = learned("inst+search4", "full");
  ASSERT_EQ(l.exit_code, 0) << l.err;
  ScratchDir dir;
  const fs::path store = dir / "copy.sqlite";
  fs::copy_file(l.store, store);
  auto listed = [&] {
    Invocation r = run_cli(dir.path(), {"knowledge", "--knowledge", store.string(), "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out, nullptr, false);
  };
  nlohmann::json before = listed();
  ASSERT_FALSE(before.is_discarded());
  ASSERT_GE(before["class_rules"].size(), 2u);
  EXPECT_TRUE(before["forgotten_rules"].empty());
  // The most believed rule induced from two examples or more.
  nlohmann::json chosen;
  for (const nlohmann::json& rule : before["class_rules"])
    if (rule["source"] == "induced" && rule["evidence"].size() >= 2 &&
        (chosen.is_null() || rule["confidence"].get<double>() > chosen["confidence"].get<double>()))
      chosen = rule;
  ASSERT_FALSE(chosen.is_null());
  const std::string subject = chosen["subject"], destination = chosen["destination"];
  const std::string text = chosen["text"];
  EXPECT_THAT(text, HasSubstr("induced from the examples"));
  Invocation plain = run_cli(dir.path(), {"knowledge", "--knowledge", store.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_THAT(plain.out, HasSubstr("For things I was never taught, I generalize:\n"));
  EXPECT_THAT(plain.out, HasSubstr("  " + text + "\n"));

  Invocation forgot = run_cli(dir.path(), {"knowledge", "forget", subject, destination, "--knowledge", store.string()});
  ASSERT_EQ(forgot.exit_code, 0) << forgot.err;
  EXPECT_THAT(forgot.out, HasSubstr("I forgot that " + text));

  nlohmann::json after = listed();
  ASSERT_EQ(after["forgotten_rules"].size(), 1u);
  EXPECT_EQ(after["forgotten_rules"][0]["text"], text);
  EXPECT_EQ(after["forgotten_rules"][0]["evidence"], chosen["evidence"]);
  EXPECT_EQ(after["class_rules"].size(), before["class_rules"].size() - 1);
  for (const nlohmann::json& rule : after["class_rules"]) EXPECT_NE(rule["text"], text);
  Invocation plain_after = run_cli(dir.path(), {"knowledge", "--knowledge", store.string()});
  const std::size_t forgotten_at = plain_after.out.find("You told me to forget these, and I do not use them:\n  " + text);
  ASSERT_NE(forgotten_at, std::string::npos) << plain_after.out;
  EXPECT_EQ(plain_after.out.find(text), forgotten_at + std::string("You told me to forget these, and I do not use them:\n  ").size());

  Invocation unknown = run_cli(dir.path(), {"knowledge", "forget", "unicorns", "--knowledge", store.string()});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("I hold no rule about \"unicorns\"."));
  Invocation nothing = run_cli(dir.path(), {"knowledge", "forget", "--knowledge", store.string()});
  EXPECT_EQ(nothing.exit_code, 2);
  EXPECT_THAT(nothing.err, HasSubstr("knowledge forget takes what the rule is about"));
  // Forgetting it again: it is no longer held.
  Invocation again = run_cli(dir.path(), {"knowledge", "forget", subject, destination, "--knowledge", store.string()});
  EXPECT_EQ(again.exit_code, 2);
  // A rule and "the rest" of its class ("container", "other container")
  // are two rules: the person is asked to say which.
  for (const nlohmann::json& rule : after["class_rules"]) {
    const std::string s = rule["subject"];
    if (s.rfind("other ", 0) != 0) continue;
    const std::string bare = s.substr(6);
    bool both = false;
    for (const nlohmann::json& other : after["class_rules"]) both = both || other["subject"] == bare;
    if (!both) continue;
    Invocation which = run_cli(dir.path(), {"knowledge", "forget", bare, "--knowledge", store.string()});
    EXPECT_EQ(which.exit_code, 2);
    EXPECT_THAT(which.err, HasSubstr("Say which, for example: forget \""));
    break;
  }
}

}  // namespace
}  // namespace apprentice
