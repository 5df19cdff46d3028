// A TidyBot scenario as a world: names as the world's words, receptacles
// and surfaces told apart by WordNet, look-alike places by their
// properties, and the intent the person's placements give.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "benchmark/tidybot_scenarios.h"
#include "benchmark/tidybot_world.h"
#include "common/paths.h"
#include "language/generation.h"
#include "tidybot_fixtures.h"

namespace apprentice::benchmark {
namespace {

using ::testing::ElementsAre;

TEST(TidyBotNames, ObjectsBecomeHyphenatedCategories) {
  EXPECT_EQ(item_category("Rubik's cube"), "rubiks-cube");
  EXPECT_EQ(item_category("Cheez-It crackers"), "cheez-it-crackers");
  EXPECT_EQ(item_category("T-shirt"), "t-shirt");
  EXPECT_EQ(item_category("  Uncle Ben's white rice "), "uncle-bens-white-rice");
  EXPECT_EQ(item_category("V8 juice"), "v8-juice");
  // The agent says "the" before a name itself: not "the the los angeles
  // times newspaper".
  EXPECT_EQ(item_category("The Los Angeles Times newspaper"), "los-angeles-times-newspaper");
  EXPECT_EQ(item_category("The"), "the");
}

TEST(TidyBotNames, LeadingPositionAndSizeWordsAreProperties) {
  PlaceName top = place_name("top drawer");
  EXPECT_EQ(top.category, "drawer");
  EXPECT_THAT(top.properties, ElementsAre("top"));
  PlaceName box = place_name("small cardboard box");
  EXPECT_EQ(box.category, "cardboard-box");
  EXPECT_THAT(box.properties, ElementsAre("small"));
  EXPECT_EQ(place_name("bin 1").category, "bin-1");
  EXPECT_TRUE(place_name("bin 1").properties.empty());
  EXPECT_EQ(place_name("coffee table").category, "coffee-table");
  // A word alone is the category, even a position word.
  EXPECT_EQ(place_name("left").category, "left");
}

class TidyBotWorld : public ::testing::Test {
 protected:
  void SetUp() override {
    auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
    ASSERT_TRUE(scenarios) << scenarios.error().describe();
    scenarios_ = std::move(*scenarios);
  }
  Result<BenchmarkWorld> build(std::size_t which, bool seen) {
    const TidyBotScenario& s = scenarios_.at(which);
    return build_world(s, seen ? s.seen_objects : s.unseen_objects,
                       apprentice::testing::source_path("data/domains/kitchen.pddl"), lexicon_);
  }
  std::vector<TidyBotScenario> scenarios_;
  language::Lexicon lexicon_ = language::Lexicon::open_default();
};

TEST_F(TidyBotWorld, ObjectsStartOnTheCartAndThePlacesAreTheReceptacles) {
  auto world = build(0, false);
  ASSERT_TRUE(world) << world.error().describe();
  const World& w = world->scenario.world;
  EXPECT_EQ(w.location, "bedroom");
  EXPECT_EQ(world->scenario.task.name, "tidy bedroom");
  ASSERT_EQ(world->objects.size(), 3u);
  for (const auto& [name, id] : world->objects) EXPECT_EQ(language::place_of(w, id), world->cart) << name;
  EXPECT_EQ(world->scenario.objects_to_tidy().size(), 3u);
  ASSERT_EQ(world->places.size(), 2u);
  EXPECT_EQ(world->receptacle_name(world->places[1].second), "toy chest");
  EXPECT_EQ(world->receptacle_name(world->cart), "");
  // "polo shirt 2" goes where polo shirts go: another polo shirt.
  EXPECT_EQ(w.universe->info(world->objects[2].second).category, "polo-shirt");
}

TEST_F(TidyBotWorld, ContainersHoldThingsInAndTheRestHoldThingsOn) {
  auto bedroom = build(0, true);
  ASSERT_TRUE(bedroom) << bedroom.error().describe();
  const Universe& u = *bedroom->scenario.world.universe;
  if (!lexicon_.has_wordnet()) GTEST_SKIP() << "no WordNet: every place is a surface";
  EXPECT_EQ(u.info(bedroom->places[0].second).kind, ObjectKind::kReceptacle);  // hamper
  EXPECT_EQ(u.info(bedroom->places[1].second).kind, ObjectKind::kReceptacle);  // toy chest: a chest
  auto kitchen = build(1, true);
  ASSERT_TRUE(kitchen) << kitchen.error().describe();
  const Universe& k = *kitchen->scenario.world.universe;
  const ObjectInfo& top = k.info(kitchen->places[0].second);
  EXPECT_EQ(top.kind, ObjectKind::kSurface);
  EXPECT_EQ(top.category, "shelf");
  EXPECT_THAT(top.properties, ElementsAre("top"));
  EXPECT_EQ(language::noun_for(kitchen->scenario.world, kitchen->places[1].second), "the bottom shelf");
}

TEST_F(TidyBotWorld, TheIntentIsWhereThePersonPutsEachObject) {
  auto world = build(0, true);
  ASSERT_TRUE(world) << world.error().describe();
  const Scenario& s = world->scenario;
  for (const auto& [name, id] : world->objects) {
    auto goal = s.intended_goal("clear", id);
    ASSERT_TRUE(goal) << name;
    ASSERT_EQ(goal->literals.size(), 1u);
    EXPECT_EQ(world->receptacle_name(goal->literals[0].fact.args[1]), scenarios_[0].destination(name)) << name;
  }
}

// Every scenario of the development half builds, for both of its worlds.
TEST(TidyBotWorlds, EveryScenarioOfTheDevelopmentHalfBuilds) {
  const auto path = apprentice::testing::shared_path("data/tidybot-benchmark/scenarios-dev.yml");
  APPRENTICE_REQUIRE_SHARED(path);
  auto scenarios = load_tidybot_scenarios(path);
  ASSERT_TRUE(scenarios) << scenarios.error().describe();
  language::Lexicon lexicon = language::Lexicon::open_default();
  for (const TidyBotScenario& s : *scenarios) {
    for (const auto* objects : {&s.seen_objects, &s.unseen_objects}) {
      auto world = build_world(s, *objects, apprentice::testing::source_path("data/domains/kitchen.pddl"), lexicon);
      ASSERT_TRUE(world) << world.error().describe();
      EXPECT_EQ(world->objects.size(), objects->size());
      EXPECT_EQ(world->places.size(), s.receptacles.size());
    }
  }
}

}  // namespace
}  // namespace apprentice::benchmark
