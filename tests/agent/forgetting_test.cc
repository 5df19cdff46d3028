// "forget X" decided without a session (agent/forgetting.h): a kind here,
// a kind known elsewhere by its plural or last word, a rule said, and
// "which one?" when the words fit several.
#include "agent/forgetting.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

GoalKey key(const std::string& kind) { return GoalKey{"tidy office", "clear", kind, "desk"}; }

ClassRule person_rule(const std::string& class_name, const std::string& place) {
  ClassRule rule;
  rule.class_name = class_name;
  rule.destination = Destination{"in", GoalTemplateArgument{false, place, {}}, {}};
  rule.source = RuleSource::kPerson;
  rule.said = class_name + " go in the " + place;
  return rule;
}

class Forgetting : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* kind : {"ceramic-plate", "paper-plate", "stapler", "newspaper"})
      goals_.add(GoalKnowledge{key(kind), {}, {}});
  }
  GoalMemory goals_;
};

TEST_F(Forgetting, AKindHereIsForgottenWithEveryGoalOfIt) {
  goals_.add(GoalKnowledge{GoalKey{"tidy office", "clear", "stapler", "shelf"}, {}, {}});
  ForgetDecision d = decide_forget("the stapler", std::string("stapler"), goals_, {});
  EXPECT_EQ(d.kind, ForgetDecision::Kind::kGoals);
  EXPECT_EQ(d.category, "stapler");
  EXPECT_EQ(d.goals.size(), 2u);
  EXPECT_THAT(d.reply, HasSubstr("stapler"));
}

// Not here, but known: by its plural, or by the last word of two kinds.
TEST_F(Forgetting, AKindKnownElsewhereIsFoundByItsPluralOrAskedWhich) {
  ForgetDecision staplers = decide_forget("staplers", std::nullopt, goals_, {});
  EXPECT_EQ(staplers.kind, ForgetDecision::Kind::kGoals);
  EXPECT_THAT(staplers.goals, ElementsAre(key("stapler")));
  ForgetDecision plates = decide_forget("plates", std::nullopt, goals_, {});
  EXPECT_EQ(plates.kind, ForgetDecision::Kind::kWhichKind);
  EXPECT_THAT(plates.goals, IsEmpty());
  EXPECT_THAT(plates.reply, HasSubstr("ceramic plate"));
}

// "forget paper", with a rule about paper things and a newspaper that the
// reader calls paper: the rule, not the newspaper's goal. Named by its own
// kind ("forget the newspaper"), the kind.
TEST_F(Forgetting, ARuleNamedByTheWordsComesBeforeAKindTheReaderStretched) {
  const std::vector<ClassRule> rules{person_rule("paper", "recycling-bin")};
  ForgetDecision paper = decide_forget("paper", std::string("newspaper"), goals_, rules);
  EXPECT_EQ(paper.kind, ForgetDecision::Kind::kRules);
  ASSERT_EQ(paper.rules.size(), 1u);
  EXPECT_EQ(paper.rules.front().class_name, "paper");
  EXPECT_THAT(paper.goals, IsEmpty());
  ForgetDecision newspaper = decide_forget("newspaper", std::string("newspaper"), goals_, rules);
  EXPECT_EQ(newspaper.kind, ForgetDecision::Kind::kGoals);
  EXPECT_THAT(newspaper.rules, IsEmpty());
}

TEST_F(Forgetting, TwoRulesSaidDifferentlyAreAskedWhich) {
  const std::vector<ClassRule> rules{person_rule("toys", "storage-box"), person_rule("toys", "basket")};
  ForgetDecision d = decide_forget("toys", std::nullopt, goals_, rules);
  EXPECT_EQ(d.kind, ForgetDecision::Kind::kWhichRule);
  EXPECT_THAT(d.rules, IsEmpty());
  EXPECT_THAT(d.reply, HasSubstr("basket"));
}

TEST_F(Forgetting, NothingKnownIsSaidPlainly) {
  ForgetDecision d = decide_forget("zebra", std::nullopt, goals_, {});
  EXPECT_EQ(d.kind, ForgetDecision::Kind::kNothing);
  EXPECT_THAT(d.goals, IsEmpty());
  EXPECT_THAT(d.rules, IsEmpty());
  EXPECT_THAT(d.reply, HasSubstr("zebra"));
}

}  // namespace
}  // namespace apprentice
