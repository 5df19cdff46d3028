// A person's rule as the preference model's class rules (agent/person_rule.h).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/person_rule.h"
#include "common/paths.h"
#include "world/scenario.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

constexpr const char* kRoom = R"(name: bedroom
domain: data/domains/kitchen.pddl
location: bedroom
places:
  - {category: cart, kind: surface}
  - {category: hamper, kind: receptacle}
  - {category: shelf, kind: surface, properties: [left]}
  - {category: shelf, kind: surface, properties: [right]}
  - {category: bed, kind: surface}
objects:
  - {category: sweater, at: cart1}
)";

class PersonRule : public ::testing::Test {
 protected:
  void SetUp() override {
    auto scenario = parse_scenario(kRoom, apprentice::testing::source_path("bedroom.yaml"));
    ASSERT_TRUE(scenario) << scenario.error().describe();
    scenario_ = std::move(*scenario);
  }
  std::vector<ClassRule> rules(std::string_view text) const {
    auto reading = language::read_rule(scenario_.world, lexicon_, text);
    EXPECT_TRUE(reading) << text;
    if (!reading) return {};
    return class_rules_of(scenario_.world, *reading, RuleSource::kPerson, std::string(text),
                          GoalScope{"tidy bedroom", "clear", "cart"}, 0.9);
  }
  Scenario scenario_;
  language::Lexicon lexicon_ = language::Lexicon::open_default();
};

TEST_F(PersonRule, AClassAsSaidToAPlaceTellsItsLookAlikesApart) {
  auto said = rules("Put clothes in the hamper and books on the left shelf.");
  ASSERT_EQ(said.size(), 2u);
  EXPECT_EQ(said[0].class_name, "clothes");
  EXPECT_THAT(said[0].modifiers, IsEmpty());
  EXPECT_EQ(said[0].destination.relation, "in");
  EXPECT_EQ(said[0].destination.place.category, "hamper");
  EXPECT_THAT(said[0].destination.place.properties, IsEmpty()) << "one hamper: no property needed";
  EXPECT_EQ(said[1].destination.relation, "on");
  EXPECT_THAT(said[1].destination.place.properties, ElementsAre("left"));
  EXPECT_EQ(said[1].source, RuleSource::kPerson);
  EXPECT_EQ(said[1].said, "Put clothes in the hamper and books on the left shelf.");
  EXPECT_EQ(said[1].scope, (GoalScope{"tidy bedroom", "clear", "cart"}));
  EXPECT_DOUBLE_EQ(said[1].confidence, 0.9);
}

TEST_F(PersonRule, GeneralThingsAreTheirModifiersAndOtherIsTheRest) {
  auto said = rules("heavy items on the left shelf, light ones on the right, other clothes on the bed, and everything "
                    "else in the hamper");
  ASSERT_EQ(said.size(), 4u);
  EXPECT_EQ(said[0].class_name, "");
  EXPECT_THAT(said[0].modifiers, ElementsAre("heavy"));
  EXPECT_THAT(said[1].modifiers, ElementsAre("light"));
  EXPECT_THAT(said[1].destination.place.properties, ElementsAre("right"));
  EXPECT_EQ(said[2].class_name, "clothes");
  EXPECT_TRUE(said[2].rest);
  EXPECT_EQ(said[3].class_name, "");
  EXPECT_TRUE(said[3].rest);
  EXPECT_THAT(said[3].modifiers, IsEmpty());
}

TEST_F(PersonRule, SeveralPlacesShareTheConfidenceAndAThingIsNoRule) {
  auto said = rules("Books go on the shelves.");
  ASSERT_EQ(said.size(), 2u);
  EXPECT_DOUBLE_EQ(said[0].confidence + said[1].confidence, 0.9);
  EXPECT_THAT(said[0].destination.place.properties, ElementsAre("left"));
  EXPECT_THAT(said[1].destination.place.properties, ElementsAre("right"));
  EXPECT_THAT(rules("the sweater goes in the hamper"), IsEmpty());
}

}  // namespace
}  // namespace apprentice
