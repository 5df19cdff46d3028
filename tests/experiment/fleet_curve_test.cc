// The fleet's prior through the agent (issue 23): households taught one
// after another into one store; for a kind a household never taught, what
// the others chose is offered as a yes/no that says where it comes from,
// and the n-th household's teacher says less than the first's.
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "experiment/fleet_curve.h"
#include "face/apprentice.h"
#include "common/paths.h"
#include "common/scratch.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

Scenario kitchen() {
  auto scenario = load_world(testing::scenario_path("tidy-kitchen"));
  EXPECT_TRUE(scenario.has_value()) << scenario.error().describe();
  return *scenario;
}

TEST(VaryIntent, ChangesEachKindsPlaceWithTheChanceGivenToAPlaceTheIntentUses) {
  const Scenario scenario = kitchen();
  std::mt19937 random(7);
  int varied = -1;
  Scenario same = vary_intent(scenario, 0.0, random, varied);
  EXPECT_EQ(varied, 0);
  ASSERT_EQ(same.intent.size(), scenario.intent.size());
  Scenario all = vary_intent(scenario, 1.0, random, varied);
  EXPECT_EQ(varied, static_cast<int>(scenario.intent.size()));
  for (std::size_t i = 0; i < scenario.intent.size(); ++i) {
    EXPECT_EQ(same.intent[i].place, scenario.intent[i].place);
    EXPECT_NE(all.intent[i].place, scenario.intent[i].place) << scenario.intent[i].category;
    bool used = false;
    for (const IntentEntry& e : scenario.intent) used = used || (e.place == all.intent[i].place && e.closed == all.intent[i].closed);
    EXPECT_TRUE(used) << all.intent[i].category << " was sent to a place the intent never uses";
  }
}

TEST(FleetPrior, TheSecondHouseholdIsAskedWhatTheFirstChoseAndSaysLess) {
  testing::ScratchDir scratch(/*in_memory=*/true);
  const Scenario scenario = kitchen();
  FleetCurveOptions options;
  options.knowledge = (scratch / "fleet.sqlite").string();
  options.households = 3;
  options.vary = 0;
  auto curve = run_fleet_curve(scenario, options);
  ASSERT_TRUE(curve.has_value()) << curve.error().describe();
  ASSERT_EQ(curve->size(), 3u);
  const HouseholdEffort& first = (*curve)[0];
  const HouseholdEffort& second = (*curve)[1];
  const HouseholdEffort& third = (*curve)[2];
  // The first household is taught as in Table 3's instruction row.
  EXPECT_EQ(first.counts.instructions, 48);
  EXPECT_EQ(first.counts.words, 636);
  EXPECT_EQ(first.counts.yes_no, 0);
  EXPECT_EQ(first.goals_from_fleet, 0);
  // The second is asked yes/no about what the first chose, says yes (the
  // same places are wanted), and needs fewer instructions and words.
  EXPECT_GT(second.goals_from_fleet, 0);
  EXPECT_GT(second.counts.yes_no, 0);
  EXPECT_EQ(second.counts.yes, second.counts.yes_no);
  EXPECT_LT(second.counts.instructions, first.counts.instructions);
  EXPECT_LT(second.counts.words, first.counts.words);
  EXPECT_THAT(second.transcript, HasSubstr("In the one other household I know of, the "));
  EXPECT_THAT(second.transcript, HasSubstr(". Here too?"));
  EXPECT_THAT(first.transcript, Not(HasSubstr("household")));
  EXPECT_THAT(third.transcript, HasSubstr("In all 2 other households I know of, the "));
  EXPECT_LE(third.counts.instructions, second.counts.instructions);
  for (const HouseholdEffort& h : *curve) EXPECT_EQ(h.assertions_achieved, h.assertions_total) << h.household;

  // Without the prior the policy rules are still shared, but nothing is
  // offered: no yes/no, every goal described in words. (Table 3 counts a
  // yes/no answer as an instruction too.)
  options.fleet_prior = false;
  auto without = run_fleet_curve(scenario, options);
  ASSERT_TRUE(without.has_value()) << without.error().describe();
  const DialogueCounts& alone = (*without)[1].counts;
  EXPECT_EQ(alone.yes_no, 0);
  EXPECT_EQ((*without)[1].goals_from_fleet, 0);
  EXPECT_GT(alone.words, second.counts.words);
  EXPECT_GT(alone.instructions, second.counts.instructions - second.counts.yes_no);
}

// A household that wants another place than the fleet says no, and is
// asked where instead: its own choice is kept, and the fleet's is not
// taken for it.
TEST(FleetPrior, AHouseholdThatWantsOtherPlacesSaysNoAndKeepsItsOwn) {
  testing::ScratchDir scratch(/*in_memory=*/true);
  const Scenario scenario = kitchen();
  FleetCurveOptions options;
  options.knowledge = (scratch / "fleet.sqlite").string();
  options.households = 2;
  options.vary = 0.5;
  options.seed = 3;
  auto curve = run_fleet_curve(scenario, options);
  ASSERT_TRUE(curve.has_value()) << curve.error().describe();
  const HouseholdEffort& second = (*curve)[1];
  ASSERT_GT(second.varied_kinds, 0);
  EXPECT_GT(second.counts.yes_no, second.counts.yes) << "some of the fleet's places were refused";
  EXPECT_EQ(second.assertions_achieved, second.assertions_total);
}

}  // namespace
}  // namespace apprentice
