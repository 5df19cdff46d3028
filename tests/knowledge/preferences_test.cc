// The preference model's own logic, over a small table of classes shaped
// like WordNet's (the sizes are WordNet 3.0's hyponym counts, rounded):
// induction by the size principle, modifier rules, rest rules and
// exceptions, what a rule covers, and the decision that combines sources.
// The same with WordNet itself is in tests/agent/concept_source_test.cc.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/decision.h"
#include "knowledge/induction.h"
#include "knowledge/preferences.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;

Destination on(const std::string& place) { return Destination{"on", GoalTemplateArgument{false, place, {}}, {}}; }
Destination in(const std::string& place) { return Destination{"in", GoalTemplateArgument{false, place, {}}, {}}; }

// A class chain from the kind up: {name, size} pairs, nearest first.
KindProfile thing(const std::string& kind, std::vector<std::pair<std::string, double>> chain,
                  std::vector<std::string> modifiers = {}) {
  KindProfile p;
  p.kind = kind;
  p.head = kind;
  p.modifiers = std::move(modifiers);
  int depth = 0;
  for (auto& [name, size] : chain) p.classes.push_back(ConceptClass{"id:" + name, name, 1.0, size, depth++});
  return p;
}

const std::vector<std::pair<std::string, double>> kAbove = {{"produce", 700}, {"food", 1600}, {"matter", 9000},
                                                            {"entity", 82115}};
KindProfile fruit(const std::string& kind) {
  auto chain = kAbove;
  chain.insert(chain.begin(), {{kind, 1}, {"edible fruit", 197}});
  return thing(kind, chain);
}
KindProfile vegetable(const std::string& kind) {
  auto chain = kAbove;
  chain.insert(chain.begin(), {{kind, 1}, {"vegetable", 300}});
  return thing(kind, chain);
}
KindProfile toy(const std::string& kind, std::vector<std::string> modifiers = {}) {
  return thing(kind, {{kind, 1}, {"plaything", 60}, {"artifact", 10000}, {"entity", 82115}}, std::move(modifiers));
}

TEST(Induction, TheBananaAndTheAppleGiveEdibleFruitNotFood) {
  std::vector<PlacementExample> examples = {{fruit("banana"), on("coffee-table")}, {fruit("apple"), on("coffee-table")}};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{"tidy", "clear", "floor"});
  ASSERT_FALSE(rules.empty());
  EXPECT_EQ(rules.front().class_name, "edible fruit");
  EXPECT_EQ(rules.front().class_id, "id:edible fruit");
  EXPECT_THAT(rules.front().evidence, ElementsAre("banana", "apple"));
  EXPECT_GT(rules.front().confidence, 0.6);
  EXPECT_FALSE(rules.front().rest);
  EXPECT_EQ(rules.front().scope, (GoalScope{"tidy", "clear", "floor"}));
  for (const ClassRule& rule : rules) EXPECT_NE(rule.class_name, "entity");
  // "food" may follow, far behind.
  for (const ClassRule& rule : rules)
    if (rule.class_name == "food") {
      EXPECT_LT(rule.confidence, rules.front().confidence / 4);
    }
}

TEST(Induction, OneExampleLeavesTheBeliefSpreadAndNamesNoRuleForItsKindAlone) {
  std::vector<PlacementExample> examples = {{fruit("banana"), on("coffee-table")}};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  // The kind itself explains one example best (size 1): that is the
  // example, which memory has, so no rule names it; the classes above it
  // share what belief is left.
  for (const ClassRule& rule : rules) {
    EXPECT_NE(rule.class_name, "banana");
    EXPECT_LT(rule.confidence, 0.5);
  }
}

TEST(Induction, AClassThatHoldsAnotherDestinationsExamplesIsTheRest) {
  // Fruit in the bowl; a carrot and a pear in the basket: what the basket's
  // examples share best is "produce", which holds the bowl's fruit too.
  std::vector<PlacementExample> examples = {{fruit("banana"), in("bowl")},
                                            {fruit("apple"), in("bowl")},
                                            {vegetable("carrot"), in("basket")},
                                            {fruit("pear"), in("basket")}};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  ASSERT_FALSE(rules.empty());
  const ClassRule* produce = nullptr;
  for (const ClassRule& r : rules)
    if (r.destination == in("basket") && r.class_name == "produce") produce = &r;
  ASSERT_NE(produce, nullptr);
  EXPECT_TRUE(produce->rest);
  EXPECT_TRUE(produce->exceptions.empty());
  EXPECT_THAT(produce->evidence, ElementsAre("carrot", "pear"));
  // The bowl's own rule is no rest, but the pear in the basket, which only
  // the larger "produce" takes there, is its exception.
  EXPECT_EQ(rules.front().class_name, "edible fruit");
  EXPECT_FALSE(rules.front().rest);
  EXPECT_THAT(rules.front().exceptions, ElementsAre("pear"));
}

TEST(Induction, ModifiersEveryExampleSharesAndNoOtherHasMakeARule) {
  std::vector<PlacementExample> examples = {{toy("plastic fork", {"plastic"}), in("cabinet")},
                                            {toy("plastic cup", {"plastic"}), in("cabinet")},
                                            {toy("steel fork", {"steel"}), in("sink")}};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  ASSERT_FALSE(rules.empty());
  EXPECT_THAT(rules.front().modifiers, ElementsAre("plastic"));
  EXPECT_EQ(rules.front().destination, in("cabinet"));
  EXPECT_TRUE(rules.front().class_name.empty());
  // One example with "steel" is no rule.
  for (const ClassRule& r : rules)
    if (r.destination == in("sink")) {
      EXPECT_TRUE(r.modifiers.empty());
    }
}

TEST(RuleProposals, TheOrangeGoesWhereTheFruitRuleSays) {
  std::vector<PlacementExample> examples = {{fruit("banana"), on("coffee-table")},
                                            {fruit("apple"), on("coffee-table")},
                                            {toy("lego brick"), in("storage-box")},
                                            {toy("toy car"), in("storage-box")}};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  std::vector<DestinationProposal> proposals = rule_proposals(rules, fruit("orange"), RuleSource::kInduced);
  ASSERT_FALSE(proposals.empty());
  EXPECT_EQ(proposals.front().destination, on("coffee-table"));
  // No surer than the rule is of its class ("edible fruit" rather than
  // "produce" or "food", from two examples).
  ASSERT_TRUE(proposals.front().rule.has_value());
  EXPECT_GT(proposals.front().confidence, 0.8);
  EXPECT_LE(proposals.front().confidence, proposals.front().rule->confidence);
  EXPECT_EQ(proposals.front().source, ProposalSource::kInducedRule);
  ASSERT_TRUE(proposals.front().rule.has_value());
  EXPECT_EQ(proposals.front().rule->class_name, "edible fruit");
  EXPECT_THAT(proposals.front().evidence, ElementsAre("banana", "apple"));
  // Something no rule covers gets nothing.
  EXPECT_TRUE(rule_proposals(rules, thing("stapler", {{"stapler", 1}}), RuleSource::kInduced).empty());
  // Nor do rules of another source count.
  EXPECT_TRUE(rule_proposals(rules, fruit("orange"), RuleSource::kPerson).empty());
}

TEST(RuleProposals, AnExceptionIsNotCoveredAndARestRuleYieldsToOthers) {
  ClassRule fruit_rule{"edible fruit", "id:edible fruit", {}, false, on("table"), {"lemon"}, RuleSource::kPerson,
                       "fruit on the table", {}, 0.9, {}};
  ClassRule rest{"food", "id:food", {}, true, in("pantry"), {}, RuleSource::kPerson, "other food in the pantry",
                 {}, 0.9, {}};
  EXPECT_GT(rule_covers(fruit_rule, fruit("orange")), 0);
  EXPECT_EQ(rule_covers(fruit_rule, fruit("lemon")), 0);
  std::vector<ClassRule> rules = {fruit_rule, rest};
  auto orange = rule_proposals(rules, fruit("orange"), RuleSource::kPerson);
  ASSERT_EQ(orange.size(), 1u);
  EXPECT_EQ(orange.front().destination, on("table"));
  auto carrot = rule_proposals(rules, vegetable("carrot"), RuleSource::kPerson);
  ASSERT_EQ(carrot.size(), 1u);
  EXPECT_EQ(carrot.front().destination, in("pantry"));
  // The lemon is the fruit rule's exception, so only the rest takes it.
  auto lemon = rule_proposals(rules, fruit("lemon"), RuleSource::kPerson);
  ASSERT_EQ(lemon.size(), 1u);
  EXPECT_EQ(lemon.front().destination, in("pantry"));
}

TEST(Destination, AGoalTemplateThatOnlyPlacesIsADestination) {
  GoalTemplateArgument fridge{false, "fridge", {}};
  std::vector<GoalTemplateLiteral> goal = {{"in", true, {{true, "", {}}, fridge}}, {"closed", true, {fridge}}};
  auto d = destination_of(goal);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->relation, "in");
  EXPECT_EQ(d->place.category, "fridge");
  ASSERT_EQ(d->doors.size(), 1u);
  EXPECT_EQ(destination_literals(*d), goal);
  EXPECT_EQ(format_destination(*d), "in the fridge (closed fridge)");
  // A goal about the thing itself besides its place is not a destination.
  std::vector<GoalTemplateLiteral> washed = {{"in", true, {{true, "", {}}, fridge}}, {"dirty", false, {{true, "", {}}}}};
  EXPECT_FALSE(destination_of(washed).has_value());
  EXPECT_FALSE(destination_of(std::vector<GoalTemplateLiteral>{}).has_value());
}

TEST(Decision, ALoneProposalAmongFourPlacesKeepsItsOwnConfidence) {
  std::vector<DestinationProposal> proposals = {DestinationProposal{on("table"), 0.5, ProposalSource::kSimilarity, {}, {}, ""}};
  auto beliefs = combine(proposals, 4, DecisionPolicy{});
  ASSERT_EQ(beliefs.size(), 1u);
  EXPECT_NEAR(beliefs.front().probability, 0.5, 1e-9);
}

TEST(Decision, AgreeingSourcesAreSurerThanEitherAndDisagreeingOnesAsk) {
  DecisionPolicy policy;
  policy.act_at = 0.9;
  policy.confirm_at = 0.3;
  std::vector<DestinationProposal> agree = {DestinationProposal{on("table"), 0.8, ProposalSource::kSimilarity, {"banana"}, {}, ""},
                                 DestinationProposal{on("table"), 0.8, ProposalSource::kLlmPlacement, {}, {}, ""}};
  Decision d = decide(agree, 3, policy);
  EXPECT_EQ(d.kind, Decision::Kind::kAct);
  EXPECT_GT(d.confidence, 0.9);
  ASSERT_EQ(d.support.size(), 2u);
  std::vector<DestinationProposal> disagree = {DestinationProposal{on("table"), 0.8, ProposalSource::kSimilarity, {}, {}, ""},
                                    DestinationProposal{in("box"), 0.8, ProposalSource::kLlmPlacement, {}, {}, ""}};
  Decision doubt = decide(disagree, 3, policy);
  EXPECT_EQ(doubt.kind, Decision::Kind::kConfirm);
  EXPECT_LT(doubt.confidence, 0.6);
  EXPECT_EQ(decide({}, 3, policy).kind, Decision::Kind::kAskWhere);
  EXPECT_FALSE(decide({}, 3, policy).destination.has_value());
  // Discounting a source weakens what it adds.
  policy.weights[ProposalSource::kLlmPlacement] = 0.1;
  EXPECT_LT(decide(agree, 3, policy).confidence, d.confidence);
}

TEST(Decision, WithoutTheRefusedDestinationTheNextBestIsAskedAbout) {
  std::vector<DestinationProposal> proposals = {DestinationProposal{on("table"), 0.7, ProposalSource::kSimilarity, {}, {}, ""},
                                     DestinationProposal{in("box"), 0.2, ProposalSource::kSimilarity, {}, {}, ""}};
  auto rest = without_destination(proposals, on("table"));
  ASSERT_EQ(rest.size(), 1u);
  Decision d = decide(rest, 2, DecisionPolicy{});
  ASSERT_TRUE(d.destination.has_value());
  EXPECT_EQ(*d.destination, in("box"));
}

TEST(ClassRules, AddReplacesTheSameRuleAndRemoveForgetsIt) {
  ClassRules rules;
  ClassRule fruit_rule{"edible fruit", "id:edible fruit", {}, false, on("table"), {}, RuleSource::kInduced, "",
                       {"banana"}, 0.5, {}};
  rules.add(fruit_rule);
  fruit_rule.evidence.push_back("apple");
  fruit_rule.confidence = 0.8;
  rules.add(fruit_rule);
  ASSERT_EQ(rules.size(), 1u);
  EXPECT_EQ(rules.all().front().confidence, 0.8);
  ClassRule elsewhere = fruit_rule;
  elsewhere.destination = in("box");
  rules.add(elsewhere);
  EXPECT_EQ(rules.size(), 2u);
  EXPECT_TRUE(rules.remove(fruit_rule));
  EXPECT_FALSE(rules.remove(fruit_rule));
  EXPECT_EQ(rules.size(), 1u);
  EXPECT_EQ(format_class_rule(elsewhere), "edible fruit -> in the box (induced from banana, apple; 0.80)");
}

}  // namespace
}  // namespace apprentice
