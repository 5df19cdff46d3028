// The sources of a goal for a thing without one (agent/goal_sources.h),
// built from a world and knowledge alone, without a dialogue: the person's
// rules of an earlier session hold, a destination the teacher refused for
// a kind is not proposed for it again, a rule forgotten is not proposed,
// and a goal settled in passing is taken once.
#include "agent/goal_sources.h"

#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/person_rule.h"
#include "common/paths.h"
#include "world/scenario.h"

namespace apprentice {
namespace {

constexpr const char* kRoom = R"(name: study
domain: data/domains/kitchen.pddl
location: study
places:
  - {category: desk, kind: surface}
  - {category: bookcase, kind: surface, properties: [left]}
  - {category: bookcase, kind: surface, properties: [right]}
  - {category: hamper, kind: receptacle}
objects:
  - {category: sweater, at: desk1}
  - {category: jeans, at: desk1}
  - {category: novel, at: desk1}
)";

const GoalScope kScope{"tidy study", "clear", "desk"};

class GoalSourcesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto scenario = parse_scenario(kRoom, apprentice::testing::source_path("study.yaml"));
    ASSERT_TRUE(scenario) << scenario.error().describe();
    scenario_ = std::move(*scenario);
    ASSERT_TRUE(lexicon_.has_wordnet());
  }
  const World& world() const { return scenario_.world; }
  ObjectId thing(const char* id) const { return *world().universe->find(id); }
  GoalKey key(const char* id) const {
    return GoalKey{kScope.task, kScope.subtask, world().universe->info(thing(id)).category, kScope.place};
  }
  // The knowledge of an earlier session where the person said `rule`.
  Knowledge said_before(std::string_view rule) const {
    Knowledge knowledge;
    auto reading = language::read_rule(world(), lexicon_, rule);
    EXPECT_TRUE(reading) << rule;
    if (reading)
      for (ClassRule& r : class_rules_of(world(), *reading, RuleSource::kPerson, std::string(rule), kScope, 0.9))
        knowledge.class_rules.add(std::move(r));
    return knowledge;
  }
  // The places the sources propose for `id`, by the person's rules: "in
  // hamper1".
  std::vector<std::string> by_rule(const GoalSources& sources, const char* id) const {
    std::vector<std::string> out;
    for (const DestinationProposal& p : sources.proposals_for(world(), key(id), thing(id), {}))
      if (p.source == ProposalSource::kPersonRule) out.push_back(p.destination.relation + " " + p.destination.place.category);
    return out;
  }
  Scenario scenario_;
  language::Lexicon lexicon_ = language::Lexicon::open_default();
};

TEST_F(GoalSourcesTest, APersonsRuleFromAnEarlierSessionIsProposedForWhatItCovers) {
  Knowledge knowledge = said_before("Put clothes in the hamper and books on the left bookcase.");
  ASSERT_EQ(knowledge.class_rules.size(), 2u);
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  EXPECT_EQ(sources.said_rules().size(), 2u);
  EXPECT_THAT(by_rule(sources, "sweater1"), ::testing::ElementsAre("in hamper"));
  EXPECT_THAT(by_rule(sources, "novel1"), ::testing::ElementsAre("on bookcase"));
  // Without a rule said, nothing is proposed by one.
  Knowledge none;
  GoalSources fresh(none, world(), lexicon_, nullptr);
  EXPECT_TRUE(by_rule(fresh, "sweater1").empty());
}

// Found by a fresh user: "Does the soda can go with sticky note, as you
// said". A rule said of one kind here in the singular is named with "the";
// a class in the plural as said.
TEST_F(GoalSourcesTest, TheEvidenceNamesAKindSaidInTheSingularWithItsArticle) {
  Knowledge knowledge = said_before("novel goes on the left bookcase, clothes go in the hamper.");
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  auto person_rule_only = [&](const char* id) {
    std::vector<DestinationProposal> out;
    for (DestinationProposal& p : sources.proposals_for(world(), key(id), thing(id), {}))
      if (p.source == ProposalSource::kPersonRule) out.push_back(std::move(p));
    return out;
  };
  EXPECT_EQ(evidence_phrase(world(), person_rule_only("novel1")), "with the novel, as you said");
  EXPECT_EQ(evidence_phrase(world(), person_rule_only("jeans1")), "with clothes, as you said");
}

// Found by a fresh user (stop 40): "dirty clothes go in the laundry
// basket" put the CLEAN t-shirt in the laundry basket, alone. A word of a
// rule that the world gives things as a property ("dirty") fits only the
// things that have it.
TEST_F(GoalSourcesTest, APropertySaidInARuleFitsOnlyTheThingsThatHaveIt) {
  auto laundry = parse_scenario(R"(name: bedroom
domain: data/domains/kitchen.pddl
location: bedroom
places:
  - {category: bed, kind: surface}
  - {category: hamper, kind: receptacle}
objects:
  - {category: t-shirt, at: bed1, properties: [clean]}
  - {category: t-shirt, at: bed1, properties: [dirty]}
  - {category: sock, at: bed1, properties: [dirty]}
)",
                                apprentice::testing::source_path("bedroom.yaml"));
  ASSERT_TRUE(laundry) << laundry.error().describe();
  const World& w = laundry->world;
  Knowledge knowledge;
  const GoalScope scope{"tidy bedroom", "clear", "bed"};
  auto reading = language::read_rule(w, lexicon_, "dirty clothes go in the hamper");
  ASSERT_TRUE(reading);
  for (ClassRule& r : class_rules_of(w, *reading, RuleSource::kPerson, "dirty clothes go in the hamper", scope, 0.9))
    knowledge.class_rules.add(std::move(r));
  GoalSources sources(knowledge, w, lexicon_, nullptr);
  auto by_the_rule = [&](const char* id) {
    const ObjectId o = *w.universe->find(id);
    std::vector<std::string> out;
    const GoalKey k{scope.task, scope.subtask, w.universe->info(o).category, scope.place};
    for (const DestinationProposal& p : sources.proposals_for(w, k, o, {}))
      if (p.source == ProposalSource::kPersonRule) out.push_back(p.destination.relation + " " + p.destination.place.category);
    return out;
  };
  EXPECT_THAT(by_the_rule("t-shirt2"), ::testing::ElementsAre("in hamper"));
  EXPECT_THAT(by_the_rule("sock1"), ::testing::ElementsAre("in hamper"));
  EXPECT_TRUE(by_the_rule("t-shirt1").empty());
}

TEST_F(GoalSourcesTest, ADestinationRefusedForAKindIsNotProposedForItAgain) {
  Knowledge knowledge = said_before("Put clothes in the hamper.");
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  auto proposals = sources.proposals_for(world(), key("sweater1"), thing("sweater1"), {});
  ASSERT_FALSE(proposals.empty());
  const Destination hamper = proposals.front().destination;
  sources.refuse("sweater", hamper);
  for (const DestinationProposal& p : sources.proposals_for(world(), key("sweater1"), thing("sweater1"), {}))
    EXPECT_FALSE(p.destination == hamper) << p.reason;
  // The jeans are of another kind: the rule still reaches them.
  EXPECT_THAT(by_rule(sources, "jeans1"), ::testing::ElementsAre("in hamper"));
}

TEST_F(GoalSourcesTest, ARuleForgottenIsNoLongerInUseOrProposed) {
  Knowledge knowledge = said_before("Put clothes in the hamper and books on the left bookcase.");
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  std::vector<ClassRule> in_use = sources.rules_in_use();
  auto clothes = std::find_if(in_use.begin(), in_use.end(), [](const ClassRule& r) { return r.class_name == "clothes"; });
  ASSERT_NE(clothes, in_use.end());
  sources.forget_rule(*clothes);
  EXPECT_TRUE(by_rule(sources, "jeans1").empty());
  EXPECT_THAT(by_rule(sources, "novel1"), ::testing::ElementsAre("on bookcase"));
  EXPECT_EQ(sources.rules_in_use().size(), in_use.size() - 1);
}

TEST_F(GoalSourcesTest, AGoalSettledInPassingIsTakenOnce) {
  Knowledge knowledge;
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  EXPECT_FALSE(sources.settled(thing("jeans1")));
  EXPECT_FALSE(sources.take_settled(thing("jeans1")).has_value());
  Goal goal;
  sources.settle(thing("jeans1"), goal, "yes, with the sweater");
  EXPECT_TRUE(sources.settled(thing("jeans1")));
  auto taken = sources.take_settled(thing("jeans1"));
  ASSERT_TRUE(taken.has_value());
  EXPECT_EQ(taken->second, "yes, with the sweater");
  EXPECT_FALSE(sources.settled(thing("jeans1")));
  EXPECT_FALSE(sources.take_settled(thing("jeans1")).has_value());
}

TEST_F(GoalSourcesTest, NoLlmPlacementsBeforeTheLlmIsConsulted) {
  Knowledge knowledge;
  GoalSources sources(knowledge, world(), lexicon_, nullptr);
  EXPECT_FALSE(sources.llm_consulted());
  EXPECT_FALSE(sources.llm_placed_by_persons_rule());
  EXPECT_TRUE(sources.llm_placements(world(), thing("sweater1")).empty());
  GoalSources::Asking asking;
  asking.llm = true;
  for (const DestinationProposal& p : sources.proposals_for(world(), key("sweater1"), thing("sweater1"), asking))
    EXPECT_NE(p.source, ProposalSource::kLlmPlacement);
}

}  // namespace
}  // namespace apprentice
