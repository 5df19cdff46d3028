// The agent's ConceptSource over the real WordNet (and the word vectors when
// the build has them): how names are read, what classes they get, and the
// preference model's induction on them ("fruit", not "food").
#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "common/paths.h"
#include "knowledge/induction.h"
#include "knowledge/said_rules.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;

class ConceptSourceTest : public ::testing::Test {
 protected:
  language::Lexicon lexicon_ = language::Lexicon::open_default();
  LexicalConcepts concepts_{lexicon_, nullptr};

  void SetUp() override {
    if (!lexicon_.has_wordnet()) GTEST_SKIP() << "no WordNet database";
  }
  static Destination on(const std::string& place) { return Destination{"on", GoalTemplateArgument{false, place, {}}, {}}; }
  static Destination in(const std::string& place) { return Destination{"in", GoalTemplateArgument{false, place, {}}, {}}; }
  PlacementExample example(const std::string& kind, Destination d) { return {concepts_.profile(kind), std::move(d)}; }
};

TEST(NameWords, ANameIsReadAsAPersonWritesIt) {
  auto none = [](std::string_view) { return false; };
  auto tshirt = [](std::string_view w) { return w == "t-shirt"; };
  EXPECT_THAT(name_words("The Los Angeles Times newspaper", none),
              ElementsAre("the", "los", "angeles", "times", "newspaper"));
  EXPECT_THAT(name_words("Rubik's cube", none), ElementsAre("rubik", "cube"));
  EXPECT_THAT(name_words("decorative pillow 2", none), ElementsAre("decorative", "pillow"));
  EXPECT_THAT(name_words("ceramic-plate", none), ElementsAre("ceramic", "plate"));
  EXPECT_THAT(name_words("Disney t-shirt", tshirt), ElementsAre("disney", "t-shirt"));
  EXPECT_THAT(name_words("Mr. Clean Magic Eraser", none), ElementsAre("mr", "clean", "magic", "eraser"));
}

TEST_F(ConceptSourceTest, TheHeadIsTheLongestEndingWordNetKnows) {
  KindProfile chips = concepts_.profile("Ruffles sour cream potato chips");
  EXPECT_EQ(chips.head, "potato chips");
  EXPECT_THAT(chips.modifiers, ElementsAre("ruffles", "sour", "cream"));
  ASSERT_FALSE(chips.classes.empty());
  KindProfile fork = concepts_.profile("stainless steel fork");
  EXPECT_EQ(fork.head, "fork");
  EXPECT_THAT(fork.modifiers, ElementsAre("stainless", "steel"));
  KindProfile tuna = concepts_.profile("case of canned tuna");
  EXPECT_EQ(tuna.head, "tuna");
  EXPECT_THAT(tuna.modifiers, ElementsAre("case", "canned"));
  KindProfile unknown = concepts_.profile("Skittles");
  EXPECT_EQ(unknown.head, "skittles");
  // WordNet's "skittles" is the game; that is a class, but no food.
  KindProfile plate = concepts_.profile("ceramic-plate");
  EXPECT_EQ(plate.head, "plate");
  EXPECT_THAT(plate.modifiers, ElementsAre("ceramic"));
}

TEST_F(ConceptSourceTest, ClassesAreNearestFirstAndLargerHigherUp) {
  KindProfile banana = concepts_.profile("banana");
  ASSERT_GT(banana.classes.size(), 4u);
  EXPECT_EQ(banana.classes.front().depth, 0);
  const ConceptClass* fruit = nullptr;
  const ConceptClass* food = nullptr;
  for (const ConceptClass& c : banana.classes) {
    if (c.name == "edible fruit") fruit = &c;
    if (c.name == "food" && c.id != "" && (food == nullptr || c.depth < food->depth)) food = &c;
  }
  ASSERT_NE(fruit, nullptr);
  ASSERT_NE(food, nullptr);
  EXPECT_LT(fruit->depth, food->depth);
  EXPECT_LT(fruit->size, food->size);
  EXPECT_GT(fruit->size, 50);
}

// A plural WordNet knows as a word of its own, but as nothing physical
// ("shoes": a situation, "in her shoes"), names its singular's class too,
// so that sneakers fall under a person's "shoes"; a plural that names a
// physical class of its own ("clothes": apparel) keeps it alone.
TEST_F(ConceptSourceTest, APluralIsReadAsItsSingularUnlessItIsAWordOfItsOwn) {
  auto names = [&](std::string_view words) {
    std::vector<std::string> out;
    for (const ConceptClass& c : concepts_.classes_named(words)) out.push_back(c.name);
    return out;
  };
  EXPECT_THAT(names("shoes"), ::testing::Contains("shoe"));
  const std::string shoe_id = concepts_.classes_named("shoes").front().id;
  const KindProfile sneakers = concepts_.profile("sneakers");
  EXPECT_TRUE(std::any_of(sneakers.classes.begin(), sneakers.classes.end(),
                          [&](const ConceptClass& c) { return c.id == shoe_id; }));
  EXPECT_THAT(names("clothes"), ::testing::Contains("apparel"));
  EXPECT_THAT(names("clothes"), ::testing::Not(::testing::Contains("fabric")));
  // A collective word names its parent's things too ("clothes": clothing);
  // the plural of a count noun with few kinds does not ("pots": no
  // container, or a seed packet would be one).
  EXPECT_THAT(names("clothes"), ::testing::Contains("clothing"));
  EXPECT_THAT(names("pots"), ::testing::Contains("pot"));
  EXPECT_THAT(names("pots"), ::testing::Not(::testing::Contains("container")));
}

TEST_F(ConceptSourceTest, TheBananaAndTheAppleGiveFruitNotFood) {
  std::vector<PlacementExample> examples = {example("banana", on("coffee-table")), example("apple", on("coffee-table")),
                                            example("Lego brick", in("storage-box")),
                                            example("toy car", in("storage-box"))};
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  const ClassRule* fruit = nullptr;
  for (const ClassRule& r : rules)
    if (r.destination == on("coffee-table") && fruit == nullptr) fruit = &r;
  ASSERT_NE(fruit, nullptr);
  EXPECT_EQ(fruit->class_name, "edible fruit");
  EXPECT_THAT(fruit->evidence, ElementsAre("banana", "apple"));
  // An orange goes with them, and a teddy bear does not.
  auto orange = rule_proposals(rules, concepts_.profile("orange"), RuleSource::kInduced);
  ASSERT_FALSE(orange.empty());
  EXPECT_EQ(orange.front().destination, on("coffee-table"));
  auto bear = rule_proposals(rules, concepts_.profile("teddy bear"), RuleSource::kInduced);
  for (const DestinationProposal& p : bear) EXPECT_NE(p.destination, on("coffee-table"));
}

// What `apprentice knowledge` says of the goals taught: the class each
// destination's examples support, in English, with its evidence; induced
// anew from the goals, so a forgotten goal takes its evidence away.
TEST_F(ConceptSourceTest, TheGeneralizationsAreSaidInEnglishWithTheirEvidence) {
  Knowledge knowledge;
  auto taught = [&](const std::string& kind, const Destination& d) {
    GoalKnowledge g;
    g.key = GoalKey{"tidy living room", "clear", kind, "cart"};
    g.literals = destination_literals(d);
    knowledge.goals.add(g);
  };
  taught("banana", on("coffee-table"));
  taught("apple", on("coffee-table"));
  taught("lego-brick", in("storage-box"));
  taught("toy-car", in("storage-box"));
  std::vector<std::string> lines = explain_preferences(knowledge, concepts_);
  EXPECT_THAT(lines, ::testing::Contains(::testing::AllOf(
                         ::testing::StartsWith("edible fruit goes on the coffee table, from the banana and the apple"),
                         ::testing::HasSubstr("induced from the examples"))));
  knowledge.goals.remove(GoalKey{"tidy living room", "clear", "apple", "cart"});
  for (const std::string& line : explain_preferences(knowledge, concepts_))
    EXPECT_THAT(line, ::testing::Not(::testing::HasSubstr("the apple")));
}

// "books and notebooks go on the shelf" (a fresh user's dorm room): WordNet's
// "books" are bound pages first, a textbook a published work, which is a
// book all the same, and a notebook a book with blank pages. A class word's less usual senses put a thing in the
// class by the thing's first sense only: a plastic cup is no food for
// being, rarely, a punch.
TEST_F(ConceptSourceTest, AClassWordsOtherSensesCountForAThingsFirstSense) {
  auto rule = [](const std::string& cls) {
    ClassRule said;
    said.class_name = cls;
    said.source = RuleSource::kPerson;
    return said;
  };
  EXPECT_TRUE(clause_evidence(rule("books"), concepts_.profile("textbook"), concepts_).wordnet);
  EXPECT_TRUE(clause_evidence(rule("books"), concepts_.profile("business textbook"), concepts_).wordnet);
  // A notebook is filed among communication, under "book, volume": a
  // sense under a physical thing is one too (not only the notebook computer).
  EXPECT_TRUE(clause_evidence(rule("books"), concepts_.profile("notebook"), concepts_).wordnet);
  EXPECT_FALSE(clause_evidence(rule("books"), concepts_.profile("pen"), concepts_).wordnet);
  EXPECT_TRUE(clause_evidence(rule("food"), concepts_.profile("ice cream"), concepts_).wordnet);
  EXPECT_FALSE(clause_evidence(rule("food"), concepts_.profile("plastic cup"), concepts_).wordnet);
}

}  // namespace
}  // namespace apprentice
