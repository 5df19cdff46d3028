// The preference model's own logic, over a small table of classes shaped
// like WordNet's (the sizes are WordNet 3.0's hyponym counts, rounded):
// induction by the size principle, modifier rules, rest rules and
// exceptions, what a rule covers, and the decision that combines sources.
// The same with WordNet itself is in tests/agent/concept_source_test.cc.
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/decision.h"
#include "knowledge/induction.h"
#include "knowledge/likeness.h"
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

TEST(Decision, ACalibratedSourceCountsForTheChanceItIsRightNotItsOwnFigure) {
  // Identity leaves a figure alone; scale 0 gives every figure one chance.
  EXPECT_DOUBLE_EQ(Calibration{}(0.37), 0.37);
  EXPECT_NEAR((Calibration{2.0, 0.0})(0.33), 1 / (1 + std::exp(-2.0)), 1e-12);
  EXPECT_NEAR((Calibration{2.0, 0.0})(0.5), (Calibration{2.0, 0.0})(0.9), 1e-12);
  // A scale below 1 pulls an overconfident source toward its middle.
  EXPECT_LT((Calibration{0.0, 0.5})(0.999), 0.99);
  EXPECT_GT((Calibration{0.0, 0.5})(0.001), 0.01);
  DecisionPolicy policy;
  policy.act_at = 0.95;
  policy.confirm_at = 0.3;
  // Likeness alone at 0.999 between two places acts; calibrated as a source
  // right about 94% of the time at that figure, it asks.
  std::vector<DestinationProposal> sure = {DestinationProposal{on("table"), 0.999, ProposalSource::kSimilarity, {}, {}, ""}};
  EXPECT_EQ(decide(sure, 2, policy).kind, Decision::Kind::kAct);
  policy.calibration[ProposalSource::kSimilarity] = Calibration{-0.25, 0.43};
  Decision calibrated = decide(sure, 2, policy);
  EXPECT_EQ(calibrated.kind, Decision::Kind::kConfirm);
  EXPECT_NEAR(calibrated.confidence, policy.calibrated(ProposalSource::kSimilarity, 0.999), 1e-9);
  // An underconfident source (an analogy offered at 0.33) is believed more,
  // and the dispute is judged on the calibrated figures.
  std::vector<DestinationProposal> disputing = {DestinationProposal{on("table"), 0.95, ProposalSource::kLlmPlacement, {}, {}, ""},
                                                DestinationProposal{in("box"), 0.33, ProposalSource::kAnalogy, {}, {}, ""}};
  EXPECT_FALSE(decide(disputing, 3, policy).disputed);
  policy.calibration[ProposalSource::kAnalogy] = Calibration{2.5, 0.0};
  EXPECT_TRUE(decide(disputing, 3, policy).disputed);
  // The proposals shown keep the source's own figure.
  EXPECT_DOUBLE_EQ(calibrated.support.front().confidence, 0.999);
}

TEST(Decision, ADiscountedProposalKeepsItsShareOfTheCalibratedChance) {
  DecisionPolicy policy;
  policy.act_at = 0.9;
  policy.confirm_at = 0.25;
  // A calibration that flattens the induced rules (every figure one chance,
  // about 0.82) would erase a discount taken off the figure itself; taken
  // off the calibrated chance, the examples of another task still count
  // half.
  policy.calibration[ProposalSource::kInducedRule] = Calibration{1.5, 0.0};
  DestinationProposal here{on("table"), 0.6, ProposalSource::kInducedRule, {}, {}, ""};
  DestinationProposal elsewhere = here;
  elsewhere.discount = 0.5;
  const double chance = policy.calibrated(ProposalSource::kInducedRule, 0.6);
  EXPECT_NEAR(decide(std::vector<DestinationProposal>{here}, 4, policy).confidence, chance, 1e-9);
  Decision discounted = decide(std::vector<DestinationProposal>{elsewhere}, 4, policy);
  EXPECT_NEAR(discounted.confidence, 0.5 * chance, 1e-9);
  EXPECT_EQ(discounted.kind, Decision::Kind::kConfirm);
  // Halving the figure instead is lost in the flat calibration.
  DestinationProposal halved = here;
  halved.confidence = 0.3;
  EXPECT_NEAR(decide(std::vector<DestinationProposal>{halved}, 4, policy).confidence, chance, 1e-9);
  // And a discounted source disputes only at its discounted chance.
  DestinationProposal llm{in("box"), 0.95, ProposalSource::kLlmPlacement, {}, {}, ""};
  policy.dispute_at = 0.5;
  EXPECT_TRUE(decide(std::vector<DestinationProposal>{llm, here}, 4, policy).disputed);
  EXPECT_FALSE(decide(std::vector<DestinationProposal>{llm, elsewhere}, 4, policy).disputed);
}

TEST(Decision, ASourceSureOfAnotherPlaceMakesTheAgentAskUnlessTheRestIsVerySure) {
  DecisionPolicy policy;
  policy.act_at = 0.9;
  policy.act_disputed_at = 0.95;
  policy.dispute_at = 0.5;
  // Likeness and the rules are sure of the table; the LLM is fairly sure of
  // the box.
  std::vector<DestinationProposal> proposals = {DestinationProposal{on("table"), 0.8, ProposalSource::kSimilarity, {}, {}, ""},
                                                DestinationProposal{on("table"), 0.8, ProposalSource::kInducedRule, {}, {}, ""},
                                                DestinationProposal{in("box"), 0.6, ProposalSource::kLlmPlacement, {}, {}, ""}};
  Decision d = decide(proposals, 3, policy);
  ASSERT_TRUE(d.destination.has_value());
  EXPECT_EQ(*d.destination, on("table"));
  EXPECT_TRUE(d.disputed);
  EXPECT_GT(d.confidence, 0.9);
  EXPECT_LT(d.confidence, 0.95);
  EXPECT_EQ(d.kind, Decision::Kind::kConfirm);
  // The same belief undisputed acts: a source that names the box at less
  // than dispute_at is no dispute.
  proposals.back().confidence = 0.4;
  Decision calm = decide(proposals, 3, policy);
  EXPECT_FALSE(calm.disputed);
  EXPECT_EQ(calm.kind, Decision::Kind::kAct);
  // Nor is a source the policy says does not dispute.
  proposals.back().confidence = 0.6;
  policy.not_disputing = {ProposalSource::kLlmPlacement};
  EXPECT_FALSE(decide(proposals, 3, policy).disputed);
  // A source's own second choice is no dispute either.
  policy.not_disputing.clear();
  proposals.back() = DestinationProposal{in("box"), 0.55, ProposalSource::kSimilarity, {}, {}, ""};
  EXPECT_FALSE(disputed(proposals, on("table"), 0.5));
  EXPECT_TRUE(disputed(proposals, in("box"), 0.5));
}

// Word vectors of six dimensions, made so that "clean" and "dirty" are half
// alike and "shorts" are more like "socks" (0.99) than a "t-shirt" (0.81).
std::vector<float> unit(std::vector<float> v) {
  double n = 0;
  for (float x : v) n += static_cast<double>(x) * x;
  for (float& x : v) x = static_cast<float>(x / std::sqrt(n));
  return v;
}
KindProfile worded(const std::string& kind, const std::vector<std::vector<float>>& words) {
  KindProfile p;
  p.kind = kind;
  p.word_vectors = words;
  std::vector<float> sum(words.front().size(), 0.0f);
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += words[i][k] * (i + 1 == words.size() ? 2.0f : 1.0f);
  p.vector = unit(sum);
  p.head_vector = words.back();
  if (words.size() > 1) p.modifier_vector = words.front();
  return p;
}

TEST(Likeness, WordsThatSplitTheExamplesCountMoreThanTheSharedHead) {
  const std::vector<float> clean = {1, 0, 0, 0, 0, 0}, dirty = unit({0.5f, 0.866f, 0, 0, 0, 0});
  const std::vector<float> socks = unit({0, 0, 0.9f, 0.436f, 0, 0}), tshirt = unit({0, 0, 0.8f, 0, 0.6f, 0});
  const std::vector<float> shorts = unit({0, 0, 0.9223f, 0.3655f, 0.1258f, 0});
  ASSERT_GT(cosine(shorts, socks), cosine(shorts, tshirt));
  std::vector<PlacementExample> examples = {{worded("clean t-shirt", {clean, tshirt}), on("bed")},
                                            {worded("dirty socks", {dirty, socks}), in("hamper")}};
  const KindProfile thing = worded("clean shorts", {clean, shorts});
  struct NoConcepts final : ConceptSource {
    KindProfile profile(std::string_view kind) const override { return KindProfile{std::string(kind), {}, {}, {}, {}, {}, {}, {}}; }
    std::vector<ConceptClass> classes_named(std::string_view) const override { return {}; }
    std::vector<float> vector_of(std::string_view) const override { return {}; }
  } concepts;
  std::vector<LikenessFeatures> features = likeness_features(examples, thing, {}, concepts);
  ASSERT_EQ(features.size(), 2u);
  // The whole names alone would send the shorts to the socks...
  const double to_bed = features[0].values[0], to_hamper = features[1].values[0];
  EXPECT_LT(to_bed, to_hamper);
  // ...but "clean" splits the examples, and "shorts" hardly does.
  EXPECT_GT(features[0].values[7], features[1].values[7]);
  std::vector<DestinationProposal> proposals = likeness_proposals(examples, thing, {}, concepts);
  ASSERT_FALSE(proposals.empty());
  EXPECT_EQ(proposals.front().destination, on("bed"));
  // A thing with no word vectors has none of this evidence.
  KindProfile bare = thing;
  bare.word_vectors.clear();
  EXPECT_EQ(likeness_features(examples, bare, {}, concepts)[0].values[7], -1);
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
