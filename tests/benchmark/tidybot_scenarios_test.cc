// Reading the TidyBot benchmark's own scenario format: what is kept, and
// what is refused with the line that is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "benchmark/tidybot_scenarios.h"
#include "common/paths.h"
#include "tidybot_fixtures.h"

namespace apprentice::benchmark {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Pair;

TEST(TidyBotScenarios, ReadsEveryField) {
  auto scenarios = parse_tidybot_scenarios(testing::kTwoScenarios, "two.yml");
  ASSERT_TRUE(scenarios) << scenarios.error().describe();
  ASSERT_EQ(scenarios->size(), 2u);
  const TidyBotScenario& first = scenarios->front();
  EXPECT_EQ(first.index, 7);
  EXPECT_EQ(first.line, 1);
  EXPECT_EQ(first.room, "bedroom");
  EXPECT_THAT(first.receptacles, ElementsAre("hamper", "toy chest"));
  EXPECT_THAT(first.seen_placements, ElementsAre(Pair("polo shirt", "hamper"), Pair("wooden block", "toy chest")));
  EXPECT_THAT(first.unseen_objects, ElementsAre("flannel shirt", "foam block", "polo shirt 2"));
  EXPECT_EQ(first.note, "Put shirts in the hamper and blocks in the toy chest.");
  EXPECT_EQ(first.destination("foam block"), "toy chest");
  EXPECT_EQ(first.destination("wooden block"), "toy chest");
  EXPECT_EQ(first.destination("teapot"), "");
  EXPECT_THAT(scenarios->back().tags, ElementsAre("category", "attribute"));
  EXPECT_EQ(scenarios->back().line, 28);
}

TEST(TidyBotScenarios, WithoutAnIndexAScenarioIsNumberedByItsPlace) {
  std::string text = testing::kTwoScenarios;
  text.erase(text.find("  benchmark_index: 7\n"), std::string("  benchmark_index: 7\n").size());
  auto scenarios = parse_tidybot_scenarios(text, "two.yml");
  ASSERT_TRUE(scenarios) << scenarios.error().describe();
  EXPECT_EQ(scenarios->front().index, 1);
}

struct Broken {
  std::string from, to, message;
};

TEST(TidyBotScenarios, RefusesWhatIsWrongWithItsLine) {
  const Broken cases[] = {
      {"    - toy chest\n  tags", "    - attic\n  tags", "two.yml:14:7: 'attic' is not one of the scenario's receptacles"},
      {"  - - foam block\n    - toy chest", "  - - teapot\n    - toy chest", "two.yml:24:7: 'teapot' is not one of the objects"},
      {"  room: bedroom", "  room: bedroom\n  colour: red", "two.yml:7:3: unknown key 'colour'"},
      {"  benchmark_index: 9", "  benchmark_index: 7", "benchmark_index 7 is given twice"},
      {"  benchmark_index: 9", "  benchmark_index: nine", "two.yml:29:20: expected benchmark_index"},
      {"  - - polo shirt 2\n    - hamper\n", "", "'polo shirt 2' is not placed"},
      {"  room: kitchen\n", "", "two.yml:28:3: missing key 'room'"},
      {"  - - dinner plate\n    - bottom shelf", "  - - dinner plate", "expected a placement: [object, receptacle]"},
      {"  - coffee mug\n", "  - coffee mug\n  - dinner plate\n", "'dinner plate' is both a seen and an unseen object"},
  };
  for (const Broken& c : cases) {
    std::string text = testing::kTwoScenarios;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    auto scenarios = parse_tidybot_scenarios(text, "two.yml");
    ASSERT_FALSE(scenarios) << c.message;
    EXPECT_EQ(scenarios.error().code, ErrorCode::kInvalidInput);
    EXPECT_THAT(scenarios.error().message, HasSubstr(c.message));
  }
}

TEST(TidyBotScenarios, RefusesWhatIsNotAListOfScenarios) {
  for (std::string_view text : {"", "room: kitchen", "- [1, 2]", "- {room: [unclosed"}) {
    auto scenarios = parse_tidybot_scenarios(text, "bad.yml");
    ASSERT_FALSE(scenarios) << text;
    EXPECT_EQ(scenarios.error().code, ErrorCode::kInvalidInput);
    EXPECT_THAT(scenarios.error().message, HasSubstr("bad.yml"));
  }
  auto missing = load_tidybot_scenarios("/nonexistent/scenarios.yml");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
}

// The development half: 48 scenarios, each with its placements complete.
TEST(TidyBotScenarios, ReadsTheDevelopmentHalf) {
  const auto path = apprentice::testing::shared_path("data/tidybot-benchmark/scenarios-dev.yml");
  APPRENTICE_REQUIRE_SHARED(path);
  auto scenarios = load_tidybot_scenarios(path);
  ASSERT_TRUE(scenarios) << scenarios.error().describe();
  ASSERT_EQ(scenarios->size(), 48u);
  std::size_t seen = 0, unseen = 0;
  for (const TidyBotScenario& s : *scenarios) {
    EXPECT_EQ(s.index % 2, 0) << "the development half holds the even scenarios";
    seen += s.seen_objects.size();
    unseen += s.unseen_objects.size();
  }
  EXPECT_EQ(seen, 336u);
  EXPECT_EQ(unseen, 336u);
}

}  // namespace
}  // namespace apprentice::benchmark
