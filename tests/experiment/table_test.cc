// The results table: each condition's figures beside the paper's Table 3
// row, "--" where the paper has no relevance; and completion counted over
// the scenario's goal assertions.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "experiment_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;

ConditionResult result(std::string condition, double completion, std::optional<double> relevance, int instructions,
                       int words, int yes_no) {
  ConditionResult r;
  r.condition = std::move(condition);
  r.completion_rate = completion;
  r.relevance = relevance;
  r.counts = DialogueCounts{instructions, words, yes_no, 0};
  r.agent.search_nodes = 260;
  r.llm_calls = 7;
  r.wall_ms = 1.25;
  r.objects_done = 30;
  r.objects_total = 30;
  return r;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(FormatResultsTable, ShowsEachConditionBesideThePaper) {
  std::vector<ConditionResult> results{result("instruction", 100, std::nullopt, 48, 636, 0),
                                       result("inst+llm", 100, 62.857, 70, 395, 35),
                                       result("inst+search3", 100, std::nullopt, 40, 603, 0)};
  results[1].objects_done = 29;
  std::vector<std::string> lines = lines_of(format_results_table(results, true));
  ASSERT_EQ(lines.size(), 6u);  // header, 2 x (ours, paper), ours without a paper row
  EXPECT_THAT(lines[0], HasSubstr("Completion%   Objects"));
  EXPECT_THAT(lines[0], HasSubstr("#Yes/No"));
  EXPECT_EQ(lines[1].substr(0, 26), "instruction        ours   ");
  EXPECT_THAT(lines[1], HasSubstr("100.0     30/30        --       48     636       0          260         7       1.2"));
  EXPECT_THAT(lines[2], HasSubstr("paper        100.0                  --       76     757       0"));
  EXPECT_THAT(lines[3], HasSubstr("ours         100.0     29/30      62.9       70     395      35"));
  EXPECT_THAT(lines[4], HasSubstr("paper        100.0                59.1      112     348      88"));
  EXPECT_THAT(lines[5], HasSubstr("inst+search3       ours"));
}

// The paper's Table 3 (Kirk et al., Table 3), copied by hand from the
// paper's text into these literals, as the table prints it beside ours:
// completion, relevance ("--" where the paper has none), instructions,
// words, yes/no instructions.
TEST(FormatResultsTable, PrintsThePapersTable3BesideEachOfItsConditions) {
  const std::vector<std::pair<std::string, std::string>> table3{
      {"instruction", "100.0                  --       76     757       0"},
      {"inst+search4", "100.0                  --       40     603       0"},
      {"search4+llm", "54.3                53.3       14      76       0"},
      {"inst+llm", "100.0                59.1      112     348      88"},
      {"inst+search2+llm", "100.0                40.3       94     384      67"},
      {"inst+search4+llm", "100.0                30.2       70     360      43"},
  };
  std::vector<ConditionResult> results;
  for (const auto& [condition, _] : table3) results.push_back(result(condition, 90, std::nullopt, 1, 2, 3));
  std::vector<std::string> lines = lines_of(format_results_table(results, true));
  ASSERT_EQ(lines.size(), 1 + 2 * table3.size());
  for (std::size_t i = 0; i < table3.size(); ++i) {
    const std::string& paper = lines[2 + 2 * i];
    EXPECT_EQ(paper.substr(0, 26), "                   paper  ") << table3[i].first;
    EXPECT_THAT(paper, HasSubstr(table3[i].second)) << table3[i].first;
  }
}

TEST(FormatResultsTable, ThePapersRowsOnlyBesideThePapersKitchen) {
  std::vector<std::string> lines = lines_of(format_results_table(
      {result("instruction", 100, std::nullopt, 48, 636, 0), result("inst+llm", 100, 62.857, 70, 395, 35)}, false));
  ASSERT_EQ(lines.size(), 3u);
  for (const std::string& line : lines) EXPECT_THAT(line, ::testing::Not(HasSubstr("paper")));
}

// Issue 13, items 3 and 6: an ensemble's row is labelled as such and not set
// beside the paper's; a degraded row is marked and explained.
TEST(FormatResultsTable, LabelsEnsemblesAndMarksDegradedRows) {
  ConditionResult ensemble = result("search4+llm", 70, 80.0, 14, 76, 0);
  ensemble.llm_ensemble = true;
  ConditionResult degraded = result("inst+llm", 100, std::nullopt, 48, 636, 0);
  degraded.llm_failures = 3;
  degraded.llm_stopped = true;
  std::string table = format_results_table({ensemble, degraded}, true);
  std::istringstream in(table);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 5u) << table;  // header, ensemble (no paper row), inst+llm*, its paper row, the note
  // The label column widens to fit, for every row of this table.
  EXPECT_EQ(lines[1].substr(0, 39), "search4+llm        ensemble        70.0");
  EXPECT_EQ(lines[2].substr(0, 39), "inst+llm*          ours           100.0");
  EXPECT_THAT(lines[3], HasSubstr("paper          100.0"));
  EXPECT_EQ(lines[4], "* inst+llm: degraded, the LLM failed 3 queries and was not asked again");
  EXPECT_TRUE(degraded.degraded());
  EXPECT_FALSE(ensemble.degraded());
}

TEST(FormatResultsTable, AnEmptyRunIsJustTheHeader) {
  std::string table = format_results_table({}, true);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 1);
}

TEST(CountAchievedAssertions, CountsTheIntentsAssertionsThatHold) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  // The five doors start closed and must end closed.
  EXPECT_EQ(count_achieved_assertions(scenario, scenario.world.state), 5);
  EXPECT_EQ(scenario.goal_assertions().size(), 35u);
}

TEST(CountAchievedAssertions, CompletionCountsWhatHeldAtTheStartObjectsDoNot) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  const State& start = scenario.world.state;
  EXPECT_EQ(count_objects_done(scenario, start), 0);
  EXPECT_EQ(scenario.objects_to_tidy().size(), 30u);
  // Put the ketchup in the fridge but leave the fridge open: one more
  // assertion holds (the placement) and one less (the door), and the
  // ketchup is not done, since its whole goal includes the closed door.
  const World& w = scenario.world;
  ObjectId ketchup = *w.universe->find("ketchup1"), fridge = *w.universe->find("fridge1"),
           table = *w.universe->find("table1");
  std::vector<Fact> facts(start.facts().begin(), start.facts().end());
  std::erase(facts, Fact(w.vocabulary.on, {ketchup, table}));
  std::erase(facts, Fact(w.vocabulary.closed, {fridge}));
  facts.push_back(Fact(w.vocabulary.in, {ketchup, fridge}));
  State open_fridge(facts);
  EXPECT_EQ(count_achieved_assertions(scenario, open_fridge), 5);
  EXPECT_EQ(count_objects_done(scenario, open_fridge), 0);
  facts.push_back(Fact(w.vocabulary.closed, {fridge}));
  State closed_fridge(facts);
  EXPECT_EQ(count_achieved_assertions(scenario, closed_fridge), 6);
  EXPECT_EQ(count_objects_done(scenario, closed_fridge), 1);
}

TEST(InstructionFloor, IsTheTaskStructureAndOneGoalPerGoalType) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  // The paper's inst+search4 row: 14 instructions of task structure and 26
  // goal descriptions.
  EXPECT_EQ(instruction_floor(scenario), (DialogueCounts{40, 603, 0, 0}));
  Scenario s35 = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen-35.yaml"));
  EXPECT_EQ(instruction_floor(s35).instructions, 14 + 35);
}

TEST(RunCondition, AScenarioWithoutAnIntentIsRefused) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  scenario.has_intent = false;
  scenario.intent.clear();
  auto condition = parse_condition("inst+search4");
  ASSERT_TRUE(condition.has_value());
  auto result = run_condition(scenario, *condition, testing::experiment_options());
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(result.error().message, HasSubstr("needs a scenario with a task and an intent"));
  EXPECT_THAT(result.error().message, HasSubstr("this one has no intent"));
}

TEST(RunCondition, AnLlmConditionWithoutAnLlmIsRefused) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  auto condition = parse_condition("inst+llm");
  ASSERT_TRUE(condition.has_value());
  auto result = run_condition(scenario, *condition, testing::experiment_options());
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(result.error().message, HasSubstr("--llm"));
}

TEST(RunCondition, EachRunStartsFromEmptyKnowledgeAndTheInitialWorld) {
  Scenario scenario = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
  ConditionResult first = testing::run(scenario, "inst+search4", testing::experiment_options());
  ConditionResult second = testing::run(scenario, "inst+search4", testing::experiment_options());
  EXPECT_EQ(first.counts, second.counts);
  EXPECT_EQ(first.transcript, second.transcript);
  EXPECT_EQ(first.agent.search_nodes, second.agent.search_nodes);
  EXPECT_EQ(first.counts, (DialogueCounts{40, 603, 0, 0}));
  EXPECT_EQ(first.completion_rate, 100.0);
  EXPECT_EQ(first.objects_done, 30);
  EXPECT_EQ(first.objects_total, 30);
  EXPECT_EQ(first.relevance, std::nullopt);
}

}  // namespace
}  // namespace apprentice
