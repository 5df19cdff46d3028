// The scenarios beyond the kitchen (data/scenarios, docs/scenarios.md):
// each has a surface as a destination, look-alike places told apart by
// properties and a subtask over several places; every condition without an
// LLM tidies it all, and inst+search4 hears no more than the floor. And
// experiment --knowledge-in: the kitchen's knowledge in other worlds.
#include <algorithm>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiment_fixtures.h"
#include "knowledge/store.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;

class BeyondTheKitchen : public ::testing::TestWithParam<const char*> {};

TEST_P(BeyondTheKitchen, HasASurfaceDestinationLookAlikesAndASubtaskOverSeveralPlaces) {
  Scenario scenario = testing::shipped_scenario(GetParam());
  const Universe& universe = *scenario.world.universe;
  EXPECT_TRUE(std::any_of(scenario.intent.begin(), scenario.intent.end(), [&](const IntentEntry& e) {
    return universe.info(e.place).kind == ObjectKind::kSurface;
  }));
  // Two places of one kind, told apart by their properties.
  std::map<std::string, std::set<std::vector<std::string>>> properties_by_category;
  std::map<std::string, int> places_by_category;
  for (const ObjectInfo& info : universe.objects()) {
    if (info.kind == ObjectKind::kItem) continue;
    ++places_by_category[info.category];
    properties_by_category[info.category].insert(info.properties);
  }
  bool look_alikes = false;
  for (const auto& [category, count] : places_by_category)
    if (count > 1) {
      look_alikes = true;
      EXPECT_EQ(properties_by_category[category].size(), static_cast<std::size_t>(count)) << category;
    }
  EXPECT_TRUE(look_alikes);
  EXPECT_TRUE(std::any_of(scenario.task.subtasks.begin(), scenario.task.subtasks.end(),
                          [](const Subtask& s) { return s.places.size() > 1; }));
}

TEST_P(BeyondTheKitchen, EveryConditionWithoutAnLlmTidiesItAll) {
  Scenario scenario = testing::shipped_scenario(GetParam());
  DialogueCounts floor = instruction_floor(scenario);
  for (const char* condition : {"instruction", "inst+search2", "inst+search4"}) {
    ConditionResult r = testing::run(scenario, condition, testing::experiment_options());
    EXPECT_DOUBLE_EQ(r.completion_rate, 100.0) << condition;
    EXPECT_EQ(r.objects_done, r.objects_total) << condition;
    EXPECT_EQ(r.objects_total, static_cast<int>(scenario.objects_to_tidy().size()));
    EXPECT_GE(r.counts.instructions, floor.instructions) << condition;
    if (std::string_view(condition) == "inst+search4") {
      EXPECT_EQ(r.counts.instructions, floor.instructions);
      EXPECT_EQ(r.counts.words, floor.words);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenarios, BeyondTheKitchen,
                         ::testing::Values("laundry-room", "party-cleanup", "playroom", "tidy-garage",
                                           "unpack-groceries"));

// One verb for two subtasks ("clear" the floor, then "clear" the counter):
// a book from the floor goes on the shelf, a book from the counter into the
// cupboard, and every condition without an LLM does both.
TEST(OneVerbTwice, EachSubtaskKeepsItsOwnGoals) {
  Scenario scenario = testing::load_or_die(testing::source_path("tests/experiment/data/clear-twice.yaml"));
  ASSERT_EQ(scenario.task.subtasks.size(), 2u);
  EXPECT_EQ(scenario.task.subtasks[0].verb, scenario.task.subtasks[1].verb);
  const Universe& universe = *scenario.world.universe;
  const World& world = scenario.world;
  auto goal = [&](const char* object) {
    auto g = scenario.intended_goal("clear", *universe.find(object));
    return g ? format_goal(*world.domain, universe, *g) : std::string("none");
  };
  EXPECT_EQ(goal("book1"), "(on book1 shelf1)");
  EXPECT_EQ(goal("book2"), "(and (in book2 cupboard1) (closed cupboard1))");
  EXPECT_EQ(goal("mug1"), "(and (in mug1 cupboard1) (closed cupboard1))");
  DialogueCounts floor = instruction_floor(scenario);
  for (const char* condition : {"instruction", "inst+search2", "inst+search4"}) {
    ConditionResult r = testing::run(scenario, condition, testing::experiment_options());
    EXPECT_DOUBLE_EQ(r.completion_rate, 100.0) << condition;
    EXPECT_EQ(r.objects_done, 4) << condition;
    EXPECT_EQ(r.objects_total, 4) << condition;
    EXPECT_GE(r.counts.instructions, floor.instructions) << condition;
  }
}

// --- experiment --knowledge-in ------------------------------------------------

class KnowledgeIn : public testing::ScratchTest {
 protected:
  // What inst+search4 learns in the paper's kitchen, as a store.
  std::filesystem::path kitchen_store() {
    testing::Invocation learned = testing::run_cli(
        {"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "inst+search4", "--quiet",
         "--knowledge-out", (dir_ / "kitchen").string()},
        dir_);
    EXPECT_EQ(learned.exit_code, 0) << learned.err;
    return dir_ / "kitchen" / "inst+search4.sqlite";
  }
  nlohmann::json experiment(const std::string& scenario, const std::string& conditions,
                            const std::optional<std::filesystem::path>& knowledge_in) {
    std::vector<std::string> args{"experiment", "--scenario", "data/scenarios/" + scenario + ".yaml", "--conditions",
                                  conditions, "--json"};
    if (knowledge_in) args.insert(args.end(), {"--knowledge-in", knowledge_in->string()});
    testing::Invocation run = testing::run_cli(args, dir_);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return nlohmann::json::parse(run.out, nullptr, false);
  }
};

TEST_F(KnowledgeIn, TheKitchensKnowledgeServesTheRenamedKitchenAndTheStoreIsNeverWritten) {
  std::filesystem::path store = kitchen_store();
  const std::string before = testing::read_text(store);
  ASSERT_FALSE(before.empty());
  nlohmann::json scratch = experiment("tidy-kitchen-renamed", "instruction,inst+search4", std::nullopt);
  nlohmann::json carried = experiment("tidy-kitchen-renamed", "instruction,inst+search4", store);
  ASSERT_TRUE(scratch.is_array() && carried.is_array());
  ASSERT_EQ(scratch.size(), 2u);
  ASSERT_EQ(carried.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE(carried[i]["condition"].get<std::string>());
    EXPECT_EQ(carried[i]["completion_rate"].get<double>(), 100.0);
    EXPECT_EQ(carried[i]["objects_done"], carried[i]["objects_total"]);
    EXPECT_LT(carried[i]["instructions"].get<int>(), scratch[i]["instructions"].get<int>());
    EXPECT_LT(carried[i]["words"].get<int>(), scratch[i]["words"].get<int>());
    EXPECT_TRUE(scratch[i]["transfer"]["renamed"].empty());
    EXPECT_THAT(carried[i]["transfer"]["renamed"].dump(), HasSubstr("took the refrigerator for the fridge"));
    EXPECT_FALSE(carried[i]["transfer"]["analogies"].empty());
  }
  EXPECT_EQ(testing::read_text(store), before);
}

TEST_F(KnowledgeIn, TheTableSaysWhatWasCarriedOver) {
  std::filesystem::path store = kitchen_store();
  testing::Invocation run = testing::run_cli({"experiment", "--scenario", "data/scenarios/tidy-kitchen-renamed.yaml",
                                              "--conditions", "inst+search4", "--knowledge-in", store.string()},
                                             dir_);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("every condition starts from the knowledge in"));
  EXPECT_THAT(run.out, HasSubstr("The knowledge brought in, in this world's words (every condition):"));
  EXPECT_THAT(run.out, HasSubstr("took the trash-can for the garbage"));
  EXPECT_THAT(run.out, HasSubstr("inst+search4, by analogy:"));
}

// --household with --knowledge-out: what the run learned is that
// household's, and the default household holds no goal.
TEST_F(KnowledgeIn, KnowledgeOutKeepsWhatWasLearnedAsTheHouseholdNamed) {
  testing::Invocation learned = testing::run_cli(
      {"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "instruction", "--quiet",
       "--household", "smiths", "--knowledge-out", (dir_ / "out").string()},
      dir_);
  ASSERT_EQ(learned.exit_code, 0) << learned.err;
  const std::string store = (dir_ / "out" / "instruction.sqlite").string();
  auto goals_of = [&](const std::string& household) -> long {
    testing::Invocation shown =
        testing::run_cli({"knowledge", "--knowledge", store, "--household", household, "--json"}, dir_);
    EXPECT_EQ(shown.exit_code, 0) << shown.err;
    auto json = nlohmann::json::parse(shown.out, nullptr, false);
    if (json.is_discarded() || !json.contains("goals")) return -1;
    return static_cast<long>(json["goals"].size());
  };
  EXPECT_EQ(goals_of("smiths"), 26);
  EXPECT_EQ(goals_of("default"), 0);
}

TEST_F(KnowledgeIn, AMissingStoreIsAnErrorNamingIt) {
  testing::Invocation run =
      testing::run_cli({"experiment", "--scenario", "data/scenarios/tidy-kitchen.yaml", "--conditions", "instruction",
                        "--knowledge-in", (dir_ / "none.sqlite").string()},
                       dir_);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_THAT(run.err, HasSubstr("none.sqlite"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "none.sqlite"));
}

}  // namespace
}  // namespace apprentice
