// A person's rule applied to things (knowledge/said_rules.h), over a small
// table of classes and two-dimensional "vectors": the clause a thing falls
// under by WordNet, by the words of its name, by the vectors where WordNet
// is silent, and "the rest" only where no other clause is sure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "knowledge/said_rules.h"

namespace apprentice {
namespace {

Destination in(const std::string& place) { return Destination{"in", GoalTemplateArgument{false, place, {}}, {}}; }
Destination on(const std::string& place) { return Destination{"on", GoalTemplateArgument{false, place, {}}, {}}; }

// Classes by word, and unit vectors in two dimensions: "toy" words point
// one way, "clothes" words the other.
class TableConcepts final : public ConceptSource {
 public:
  KindProfile profile(std::string_view kind) const override {
    KindProfile p;
    p.kind = std::string(kind);
    p.head = p.kind;
    return p;
  }
  std::vector<ConceptClass> classes_named(std::string_view words) const override {
    if (words == "toys") return {ConceptClass{"id:plaything", "plaything", 1, 60, 0}};
    if (words == "clothes") return {ConceptClass{"id:clothing", "clothing", 1, 300, 0}};
    if (words == "outerwear") return {ConceptClass{"id:outerwear", "outerwear", 1, 40, 0}};
    return {};
  }
  std::vector<float> vector_of(std::string_view words) const override {
    static const std::map<std::string, std::vector<float>, std::less<>> kVectors = {
        {"toys", {1, 0}}, {"electronics", {0.6f, 0.8f}}, {"clothes", {0, 1}}, {"outerwear", {0.1f, 0.995f}},
        {"sports equipment", {0.8f, 0.6f}}, {"paper", {0.28f, 0.96f}}, {"material", {0.28f, 0.96f}}};
    auto found = kVectors.find(words);
    return found == kVectors.end() ? std::vector<float>{} : found->second;
  }
};

KindProfile thing(const std::string& kind, std::vector<std::string> classes, std::vector<float> vector,
                  std::vector<std::string> modifiers = {}) {
  KindProfile p;
  p.kind = kind;
  p.head = kind;
  p.modifiers = std::move(modifiers);
  for (const std::string& c : classes) p.classes.push_back(ConceptClass{"id:" + c, c, 1, 10, 1});
  p.vector = std::move(vector);
  return p;
}

ClassRule said(const std::string& cls, Destination where, bool rest = false, std::vector<std::string> modifiers = {}) {
  ClassRule rule;
  rule.class_name = cls;
  rule.modifiers = std::move(modifiers);
  rule.rest = rest;
  rule.destination = std::move(where);
  rule.source = RuleSource::kPerson;
  rule.said = "as said";
  rule.confidence = 0.95;
  return rule;
}

// The person's rules' most confident proposal for a thing (an empty one,
// failing the test, when they propose nothing).
DestinationProposal best_of(const std::vector<ClassRule>& rules, const KindProfile& thing, const ConceptSource& concepts) {
  auto proposals = said_rule_proposals(rules, thing, RuleSource::kPerson, concepts);
  EXPECT_FALSE(proposals.empty());
  return proposals.empty() ? DestinationProposal{} : proposals.front();
}

TEST(SaidRules, WordNetPutsAThingUnderItsClause) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("toys", in("storage-box")), said("clothes", on("chair"))};
  auto proposals =
      said_rule_proposals(rules, thing("teddy bear", {"plaything"}, {0.7f, 0.7f}), RuleSource::kPerson, concepts);
  ASSERT_EQ(proposals.size(), 2u);
  EXPECT_EQ(proposals.front().destination, in("storage-box"));
  EXPECT_GT(proposals.front().confidence, 0.8);
  EXPECT_EQ(proposals.front().source, ProposalSource::kPersonRule);
  ASSERT_TRUE(proposals.front().rule.has_value());
  EXPECT_EQ(proposals.front().rule->class_name, "toys");
}

TEST(SaidRules, TheVectorsPlaceWhatWordNetDoesNotKnow) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("electronics", on("coffee-table")), said("clothes", on("chair"))};
  // A game console: no WordNet class, a vector near "electronics".
  auto proposals = said_rule_proposals(rules, thing("nintendo switch", {}, {0.6f, 0.8f}), RuleSource::kPerson, concepts);
  ASSERT_FALSE(proposals.empty());
  EXPECT_EQ(proposals.front().destination, on("coffee-table"));
  // Another source's rules say nothing.
  EXPECT_TRUE(said_rule_proposals(rules, thing("x", {}, {1, 0}), RuleSource::kLlm, concepts).empty());
}

TEST(SaidRules, TheRestTakesOnlyWhatNoOtherClauseIsSureOf) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("outerwear", in("closet")), said("clothes", on("bed"), /*rest=*/true)};
  // The parka is outerwear (and clothing): the closet, though its vector is
  // as near to "clothes".
  auto parka = said_rule_proposals(rules, thing("parka", {"outerwear", "clothing"}, {0.05f, 0.998f}),
                                   RuleSource::kPerson, concepts);
  ASSERT_FALSE(parka.empty());
  EXPECT_EQ(parka.front().destination, in("closet"));
  // The blouse is clothing, not outerwear: the bed.
  auto blouse = said_rule_proposals(rules, thing("blouse", {"clothing"}, {0, 1}), RuleSource::kPerson, concepts);
  ASSERT_FALSE(blouse.empty());
  EXPECT_EQ(blouse.front().destination, on("bed"));
}

TEST(SaidRules, TheRestIsInDoubtWhereAnotherClauseFitsToo) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("outerwear", in("closet")), said("clothes", on("bed"), /*rest=*/true)};
  // Not outerwear by WordNet, only clothing, but near "outerwear" by the
  // vectors: the rest's bed stays below what the agent acts on alone.
  const KindProfile jacket = thing("ski jacket", {"clothing"}, {0.2f, 0.98f});
  ASSERT_TRUE(clause_evidence(rules[0], jacket, concepts).fits());
  const DestinationProposal doubted = best_of(rules, jacket, concepts);
  EXPECT_EQ(doubted.destination, on("bed"));
  EXPECT_LE(doubted.confidence, SaidRuleWeights{}.rest_in_doubt * 0.95 + 1e-9);
  // Beside a clause the jacket does not fit, the rest takes it surely.
  std::vector<ClassRule> beside_toys = {said("toys", in("closet")), said("clothes", on("bed"), /*rest=*/true)};
  ASSERT_FALSE(clause_evidence(beside_toys[0], jacket, concepts).fits());
  const DestinationProposal sure = best_of(beside_toys, jacket, concepts);
  EXPECT_EQ(sure.destination, on("bed"));
  EXPECT_GT(sure.confidence, 0.9);
}

TEST(SaidRules, AClassWordNetDoesNotKnowIsItsHeadWithModifiers) {
  TableConcepts concepts;
  // "light-colored clothes" is no noun of WordNet's; "clothes" is.
  const ClassRule light = said("light-colored clothes", in("large-hamper"));
  const ClassRule split = as_head_and_modifiers(light, concepts);
  EXPECT_EQ(split.class_name, "clothes");
  EXPECT_THAT(split.modifiers, testing::ElementsAre("light-colored"));
  EXPECT_EQ(as_head_and_modifiers(said("toys", in("box")), concepts).class_name, "toys");
  std::vector<ClassRule> rules = {light, said("dark-colored clothes", in("small-hamper")), said("toys", in("box"))};
  // Clothing by WordNet, and "light" in its name: the light-colored clause.
  const KindProfile top = thing("light yellow tank top", {"clothing"}, {}, {"light", "yellow"});
  const ClauseEvidence evidence = clause_evidence(rules[0], top, concepts);
  EXPECT_TRUE(evidence.wordnet);
  EXPECT_TRUE(evidence.modifiers_in_name);
  EXPECT_TRUE(clause_evidence(rules[1], top, concepts).modifiers_missing);
  const DestinationProposal best = best_of(rules, top, concepts);
  EXPECT_EQ(best.destination, in("large-hamper"));
  EXPECT_GT(best.confidence, 0.9);
}

TEST(SaidRules, ModifiersInTheNameDecideAndAnExceptionIsHonoured) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("", in("left-box"), false, {"plastic"}), said("", in("right-box"), false, {"metal"})};
  auto cup = said_rule_proposals(rules, thing("plastic cup", {}, {}, {"plastic"}), RuleSource::kPerson, concepts);
  // Only the clause it fits: nothing says the plastic cup is metal.
  ASSERT_EQ(cup.size(), 1u);
  EXPECT_EQ(cup.front().destination, in("left-box"));
  rules[0].exceptions.push_back("plastic cup");
  auto excepted = said_rule_proposals(rules, thing("plastic cup", {}, {}, {"plastic"}), RuleSource::kPerson, concepts);
  // Not pushed onto the other clause, which it does not fit either.
  EXPECT_TRUE(excepted.empty());
}

TEST(SaidRules, AClauseGoesOnlyToAThingThatFitsIt) {
  TableConcepts concepts;
  // One clause, and a thing nothing puts in its class: WordNet does not,
  // its name does not, and its vector is far from "toys" (cosine 0.2).
  std::vector<ClassRule> rules = {said("toys", in("top-drawer"))};
  const KindProfile blanket = thing("blanket", {"bedclothes"}, {0.2f, 0.98f});
  EXPECT_FALSE(clause_evidence(rules[0], blanket, concepts).fits());
  EXPECT_TRUE(said_rule_proposals(rules, blanket, RuleSource::kPerson, concepts).empty());
  // Near enough to "toys" by the vectors alone (cosine 0.6): offered.
  const KindProfile kite = thing("kite", {}, {0.6f, 0.8f});
  EXPECT_TRUE(clause_evidence(rules[0], kite, concepts).fits());
  EXPECT_FALSE(said_rule_proposals(rules, kite, RuleSource::kPerson, concepts).empty());
  // "Everything else" fits everything.
  std::vector<ClassRule> rest = {said("", in("top-drawer"), /*rest=*/true)};
  EXPECT_TRUE(clause_evidence(rest[0], blanket, concepts).fits());
  EXPECT_FALSE(said_rule_proposals(rest, blanket, RuleSource::kPerson, concepts).empty());
}

// Where WordNet knows the class and the thing and does not put one under
// the other, the vectors relate ("brushes" and a paint pot) but do not make
// a member: the clause is offered, to be asked, below what the agent acts
// on alone. Where WordNet does not know the thing, the vectors speak.
TEST(SaidRules, AThingOnlyRelatedToAClassIsAskedAbout) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("toys", in("top-drawer"))};
  const KindProfile pot = thing("pot", {"vessel"}, {0.8f, 0.6f});
  const ClauseEvidence evidence = clause_evidence(rules[0], pot, concepts);
  EXPECT_TRUE(evidence.fits());
  EXPECT_TRUE(evidence.only_related());
  auto proposals = said_rule_proposals(rules, pot, RuleSource::kPerson, concepts);
  ASSERT_EQ(proposals.size(), 1u);
  EXPECT_GT(proposals.front().confidence, 0.25);
  EXPECT_LE(proposals.front().confidence, SaidRuleWeights{}.only_related_at_most * 0.95 + 1e-9);
  // The same vector, and no WordNet classes: the vectors decide.
  const KindProfile unknown = thing("whirligig", {}, {0.8f, 0.6f});
  EXPECT_FALSE(clause_evidence(rules[0], unknown, concepts).only_related());
  auto alone = said_rule_proposals(rules, unknown, RuleSource::kPerson, concepts);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_GT(alone.front().confidence, 0.9);
}

// A class above the thing that is named near the class word is WordNet's
// near agreement only when the thing's own name is near it too: "tools"
// and a glove's "sports equipment" are near, "tools" and "glove" are not
// (found in a greenhouse: the gloves went in the tools' bin alone).
TEST(SaidRules, ANearClassAboveAThingWhoseNameIsFarIsOnlyRelated) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("toys", in("top-drawer"))};
  const KindProfile glove = thing("glove", {"sports equipment"}, {0.1f, 0.995f});
  const ClauseEvidence far = clause_evidence(rules[0], glove, concepts);
  EXPECT_GE(far.ancestor_cosine, kNearClassCosine);
  EXPECT_LT(far.word_cosine, kFitCosine);
  EXPECT_TRUE(far.fits());
  EXPECT_TRUE(far.only_related());
  auto asked = said_rule_proposals(rules, glove, RuleSource::kPerson, concepts);
  ASSERT_EQ(asked.size(), 1u);
  EXPECT_LE(asked.front().confidence, SaidRuleWeights{}.only_related_at_most * 0.95 + 1e-9);
  // The same class above a thing whose name is near the class word: a member.
  const KindProfile kite = thing("kite", {"sports equipment"}, {0.6f, 0.8f});
  EXPECT_FALSE(clause_evidence(rules[0], kite, concepts).only_related());
  auto placed = said_rule_proposals(rules, kite, RuleSource::kPerson, concepts);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_GT(placed.front().confidence, 0.9);
}

TEST(SaidRules, TheClassWordInTheNameIsEvidence) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("toys", in("drawer")), said("clothes", in("basket"))};
  // Neither WordNet nor the vectors know the toy hammer here: its name
  // says "toy".
  KindProfile hammer = thing("toy hammer", {}, {});
  hammer.head = "hammer";
  hammer.modifiers = {"toy"};
  auto proposals = said_rule_proposals(rules, hammer, RuleSource::kPerson, concepts);
  ASSERT_FALSE(proposals.empty());
  EXPECT_EQ(proposals.front().destination, in("drawer"));
  EXPECT_GT(proposals.front().confidence, 0.5);
  ClauseEvidence evidence = clause_evidence(rules[0], hammer, concepts);
  EXPECT_TRUE(evidence.word_in_name);
  EXPECT_TRUE(evidence.sure());
  EXPECT_FALSE(clause_evidence(rules[1], hammer, concepts).word_in_name);
}

TEST(SaidRules, AnLlmsSummaryIsReadLessSurelyThanThePersonsOwnWords) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("toys", in("storage-box")), said("clothes", on("chair"))};
  std::vector<ClassRule> summary = rules;
  for (ClassRule& rule : summary) rule.source = RuleSource::kLlm;
  const KindProfile bear = thing("teddy bear", {"plaything"}, {0.7f, 0.7f});
  auto person = said_rule_proposals(rules, bear, RuleSource::kPerson, concepts);
  auto llm = said_rule_proposals(summary, bear, RuleSource::kLlm, concepts);
  ASSERT_FALSE(person.empty());
  ASSERT_FALSE(llm.empty());
  EXPECT_EQ(llm.front().destination, person.front().destination);
  EXPECT_LT(llm.front().confidence, person.front().confidence);
}

// A class of modifiers alone ("paper stuff", found by a fresh user in a
// garage: the water bottle, the soda can and the washer fluid went in the
// recycling "with paper things", alone): the names of a thing's WordNet
// classes say what it is, not what it is made of, so only its own name's
// words count, and only the name carrying the modifier places it alone.
TEST(SaidRules, AClassOfModifiersAloneIsAskedUnlessTheNameCarriesThem) {
  TableConcepts concepts;
  std::vector<ClassRule> rules = {said("", in("recycling-bin"), false, {"paper"})};
  // A class named near "paper" ("material") and a name far from it.
  const KindProfile bottle = thing("water bottle", {"material"}, {1, 0});
  EXPECT_FALSE(clause_evidence(rules[0], bottle, concepts).fits());
  EXPECT_TRUE(said_rule_proposals(rules, bottle, RuleSource::kPerson, concepts).empty());
  // A name near "paper": offered, to be asked.
  const KindProfile newspaper = thing("newspaper", {}, {0.3f, 0.95f});
  const ClauseEvidence near = clause_evidence(rules[0], newspaper, concepts);
  EXPECT_TRUE(near.fits());
  EXPECT_TRUE(near.only_related());
  auto asked = said_rule_proposals(rules, newspaper, RuleSource::kPerson, concepts);
  ASSERT_EQ(asked.size(), 1u);
  EXPECT_LE(asked.front().confidence, SaidRuleWeights{}.only_related_at_most * 0.95 + 1e-9);
  // "paper plate": the name carries it, and nothing holds it back.
  const KindProfile plate = thing("paper plate", {}, {}, {"paper"});
  EXPECT_FALSE(clause_evidence(rules[0], plate, concepts).only_related());
  auto placed = said_rule_proposals(rules, plate, RuleSource::kPerson, concepts);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_GT(placed.front().confidence, SaidRuleWeights{}.only_related_at_most * 0.95);
}

}  // namespace
}  // namespace apprentice
