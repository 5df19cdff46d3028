// WordNet through the wrapper and the Lexicon's relations. These need
// Debian's wordnet-base; without it they skip.
#include <algorithm>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "language/lexicon.h"
#include "language/reference.h"
#include "language_fixtures.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::world35;

class WithWordNet : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!grounder().lexicon().has_wordnet()) GTEST_SKIP() << "WordNet database absent";
  }
  const Lexicon& lexicon() const { return grounder().lexicon(); }
};

bool has(const std::vector<std::string>& v, std::string_view x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

std::vector<std::string> variant_phrases(const Lexicon& lexicon, std::string_view phrase) {
  std::vector<std::string> out;
  for (const PhraseVariant& v : lexicon.variants(phrase)) out.push_back(v.phrase);
  return out;
}

TEST_F(WithWordNet, MorphologyGivesSingulars) {
  EXPECT_TRUE(has(lexicon().lemmas("crackers"), "cracker"));
  EXPECT_TRUE(has(lexicon().lemmas("plastic bottles"), "plastic bottle"));
  EXPECT_TRUE(has(lexicon().lemmas("glasses"), "glass"));
  EXPECT_TRUE(lexicon().lemmas("fridge").empty());
}

TEST_F(WithWordNet, VariantsSplitCompoundsAndRepairGerunds) {
  EXPECT_TRUE(has(variant_phrases(lexicon(), "trashcan"), "trash can"));
  EXPECT_TRUE(has(variant_phrases(lexicon(), "trashcans"), "trash can"));
  EXPECT_TRUE(has(variant_phrases(lexicon(), "recycle bin"), "recycling bin"));
  EXPECT_TRUE(variant_phrases(lexicon(), "dishwasher").empty());
}

// A class word names the kinds a few steps below it, however general it
// is; a word far above them (an "object") names none.
TEST_F(WithWordNet, KindsUnderAClassWord) {
  const std::vector<std::string> garage = {"hammer", "screwdriver", "wrench", "tape-measure", "paint-can", "sponge",
                                           "glue"};
  const std::vector<std::string> tools = {"hammer", "screwdriver", "wrench"};
  EXPECT_EQ(lexicon().kinds_under("tools", garage), tools);
  EXPECT_EQ(lexicon().kinds_under("tool", garage), tools);
  EXPECT_EQ(lexicon().kinds_under("hand tools", garage), tools);
  EXPECT_TRUE(lexicon().kinds_under("objects", garage).empty());
  EXPECT_TRUE(lexicon().kinds_under("hammer", garage).empty()) << "a kind is not under itself";
  // A kind named in the plural is found by its singular.
  const std::vector<std::string> groceries = {"saltines", "cereal-box", "milk"};
  EXPECT_EQ(lexicon().kinds_under("crackers", groceries), std::vector<std::string>{"saltines"});
}

TEST_F(WithWordNet, Synonyms) {
  EXPECT_TRUE(has(lexicon().synonyms("refrigerator"), "icebox"));
  EXPECT_TRUE(has(lexicon().synonyms("trash can"), "garbage can"));
  EXPECT_TRUE(has(lexicon().synonyms("trash can"), "wastebin"));
  EXPECT_TRUE(has(lexicon().synonyms("cupboard"), "closet"));
}

std::vector<std::string> related_places(const Lexicon& lexicon, std::string_view phrase) {
  static const std::vector<std::string> places = {"table",    "counter",   "dish-rack", "sink",
                                                  "recycling-bin", "garbage", "dishwasher", "fridge",
                                                  "pantry",   "cupboard",  "drawer"};
  std::vector<std::string> out;
  for (const CategoryRelation& r : lexicon.related(phrase, places, true)) out.push_back(r.category);
  return out;
}

TEST_F(WithWordNet, RelatesOtherWordsToTheKitchensPlaces) {
  EXPECT_EQ(related_places(lexicon(), "refrigerator"), std::vector<std::string>{"fridge"});
  EXPECT_EQ(related_places(lexicon(), "trash"), std::vector<std::string>{"garbage"});
  EXPECT_EQ(related_places(lexicon(), "trash can"), std::vector<std::string>{"garbage"});
  EXPECT_EQ(related_places(lexicon(), "garbage can"), std::vector<std::string>{"garbage"});
  EXPECT_EQ(related_places(lexicon(), "wastebasket"), std::vector<std::string>{"garbage"});
  EXPECT_EQ(related_places(lexicon(), "rubbish bin"), std::vector<std::string>{"garbage"});
  EXPECT_EQ(related_places(lexicon(), "cabinet"), std::vector<std::string>{"cupboard"});
  EXPECT_EQ(related_places(lexicon(), "closet"), std::vector<std::string>{"cupboard"});
}

// A place named one step above its own name: "shelf" is WordNet's
// hypernym of "bookshelf" (and of three other kinds), "bin" of "wastebin".
TEST_F(WithWordNet, APlaceIsNamedByItsOwnHypernym) {
  const std::vector<std::string> places = {"bookshelf", "table", "sink", "drawer"};
  std::vector<std::string> out;
  for (const CategoryRelation& r : lexicon().related("shelf", places, true)) out.push_back(r.category);
  EXPECT_EQ(out, std::vector<std::string>{"bookshelf"});
  // Not for a thing: "toys" is a class, read as one (kinds_under).
  const std::vector<std::string> things = {"rattle", "sweater"};
  EXPECT_TRUE(lexicon().related("toy", things, false).empty());
}

TEST_F(WithWordNet, GeneralWordsNameNoOnePlace) {
  // A container could be the drawer, the bins, ...; an appliance the fridge
  // or the dishwasher; WordNet has 24 kinds of receptacle, one of them the
  // garbage. Words that general never name one particular place.
  EXPECT_NE(related_places(lexicon(), "container").size(), 1u);
  EXPECT_NE(related_places(lexicon(), "receptacle").size(), 1u);
  EXPECT_GT(related_places(lexicon(), "appliance").size(), 1u);
  EXPECT_TRUE(related_places(lexicon(), "kitchen").empty());
  EXPECT_TRUE(related_places(lexicon(), "knife block").empty());
}

TEST_F(WithWordNet, AmbiguousWordsAreNotGrounded) {
  const World& world = world35();
  ReferenceContext context{world, lexicon(), std::nullopt};
  // "receptacle" and "surface" are also the domain's own types.
  for (std::string_view phrase : {"container", "appliance", "furniture", "receptacle", "surface"}) {
    NounPhrase np{"the", {std::string(phrase)}};
    Resolution r = resolve(np, Role::kPlace, context);
    ASSERT_TRUE(std::holds_alternative<GroundingFailure>(r)) << phrase;
    EXPECT_EQ(std::get<GroundingFailure>(r).kind, FailureKind::kUngroundedObject) << phrase;
  }
}

TEST_F(WithWordNet, KnowsWordsOfAnyPartOfSpeech) {
  EXPECT_TRUE(lexicon().knows("recycle"));
  EXPECT_TRUE(lexicon().knows("soapy"));
  EXPECT_TRUE(lexicon().knows("dishes"));
  EXPECT_FALSE(lexicon().knows("frobnitz"));
  EXPECT_FALSE(lexicon().knows("trashcan"));
}

// The C library keeps global state; the wrapper serialises every call, so
// concurrent lookups from many threads agree with a lone one.
TEST_F(WithWordNet, IsSafeToShareBetweenThreads) {
  std::vector<std::string> expected = related_places(lexicon(), "wastebasket");
  std::vector<std::thread> threads;
  std::vector<int> ok(8, 0);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      auto wordnet = WordNet::open();
      if (!wordnet) return;
      Lexicon own(std::move(*wordnet));
      bool same = true;
      for (int i = 0; i < 5; ++i) {
        same = same && related_places(own, "wastebasket") == expected;
        same = same && has(own.lemmas("crackers"), "cracker");
        same = same && has(lexicon().synonyms("trash can"), "garbage can");
      }
      ok[static_cast<std::size_t>(t)] = same ? 1 : 0;
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(std::count(ok.begin(), ok.end(), 1), 8);
}

TEST(WordNetOpen, ReportsAMissingDatabaseAsUnavailable) {
  auto wordnet = WordNet::open(std::filesystem::path("/nonexistent/wordnet"));
  ASSERT_FALSE(wordnet.has_value());
  EXPECT_EQ(wordnet.error().code, ErrorCode::kUnavailable);
  // Reopening the default works again afterwards.
  EXPECT_TRUE(WordNet::open().has_value() || !grounder().lexicon().has_wordnet());
}

TEST(LexiconWithoutWordNet, AnswersNothing) {
  Lexicon none(std::nullopt);
  EXPECT_FALSE(none.has_wordnet());
  EXPECT_TRUE(none.lemmas("crackers").empty());
  EXPECT_TRUE(none.variants("trashcan").empty());
  EXPECT_FALSE(none.knows("fridge"));
  std::vector<std::string> places{"fridge"};
  EXPECT_TRUE(none.related("refrigerator", places, true).empty());
}

}  // namespace
}  // namespace apprentice::language
