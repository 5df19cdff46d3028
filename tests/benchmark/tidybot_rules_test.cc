// The person's rule reader (language/rule_reader.h) on sentences nobody
// here wrote: the 48 annotators' notes of the TidyBot benchmark's
// development half, and text-davinci-003's 48 summaries of the seen
// placements (llm-dev.jsonl), each in its scenario's world. First run
// (before any fix for them): every one read whole, every clause with a
// place of its world. This test keeps that floor.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "benchmark/tidybot_scenarios.h"
#include "benchmark/tidybot_world.h"
#include "common/paths.h"
#include "language/rule_reader.h"

namespace apprentice::benchmark {
namespace {

TEST(TidyBotRules, EveryNoteAndEverySummaryIsReadWhole) {
  const auto scenarios_path = apprentice::testing::shared_path("data/tidybot-benchmark/scenarios-dev.yml");
  const auto corpus_path = apprentice::testing::shared_path("data/tidybot-benchmark/llm-dev.jsonl");
  APPRENTICE_REQUIRE_SHARED(scenarios_path);
  APPRENTICE_REQUIRE_SHARED(corpus_path);
  auto scenarios = load_tidybot_scenarios(scenarios_path);
  ASSERT_TRUE(scenarios) << scenarios.error().describe();
  std::map<int, std::string> summaries;
  std::ifstream corpus(corpus_path);
  for (std::string line; std::getline(corpus, line);) {
    auto record = nlohmann::json::parse(line);
    if (record["step"] == "summary") summaries[record["scenario"].get<int>()] = record["summary"].get<std::string>();
  }
  ASSERT_EQ(summaries.size(), scenarios->size());
  language::Lexicon lexicon = language::Lexicon::open_default();
  int read_whole = 0;
  for (const TidyBotScenario& s : *scenarios) {
    std::vector<std::string> objects = s.seen_objects;
    objects.insert(objects.end(), s.unseen_objects.begin(), s.unseen_objects.end());
    auto world = build_world(s, objects, apprentice::testing::source_path("data/domains/kitchen.pddl"), lexicon);
    ASSERT_TRUE(world) << world.error().describe();
    for (const std::string& text : {s.note, summaries.at(s.index)}) {
      auto rule = language::read_rule(world->scenario.world, lexicon, text);
      ASSERT_TRUE(rule) << s.index << ": " << text;
      EXPECT_TRUE(rule->not_understood.empty()) << s.index << ": " << text << "\n  not understood: "
                                                << rule->not_understood.front();
      EXPECT_TRUE(rule->has_class_clause()) << s.index << ": " << text;
      for (const language::RuleClause& clause : rule->clauses)
        EXPECT_FALSE(clause.places.empty()) << s.index << ": " << clause.text;
      if (rule->not_understood.empty()) ++read_whole;
    }
  }
  EXPECT_EQ(read_whole, 96);
}

}  // namespace
}  // namespace apprentice::benchmark
