// Grounding in the 35-object kitchen: references, affordances, failures
// and the narrower interpret_goal / interpret_action entry points.
#include <gtest/gtest.h>

#include "language/parser.h"
#include "language/reference.h"
#include "language_fixtures.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::id;
using testing::meaning;
using testing::world35;

TEST(Grounding, NounPhrasesMatchCategoriesHyphenatedOrSpaced) {
  EXPECT_EQ(meaning("Pick up the plastic bottle."), "action (pick-up plastic-bottle1 table1)");
  EXPECT_EQ(meaning("Pick up the plastic-bottle."), "action (pick-up plastic-bottle1 table1)");
  EXPECT_EQ(meaning("Put the box of aluminum foil in the pantry."), "action (put-in box-of-aluminum-foil1 pantry1)");
  EXPECT_EQ(meaning("Put the half-and-half in the fridge."), "action (put-in half-and-half1 fridge1)");
  EXPECT_EQ(meaning("Open the Dish-Rack"), "failure affordance-mismatch openable dish-rack1");
}

TEST(Grounding, TheObjectIsTheObjectOfInterest) {
  EXPECT_EQ(meaning("Pick up the object.", id("ketchup1")), "action (pick-up ketchup1 table1)");
  EXPECT_EQ(meaning("Pick up the object."), "failure ungrounded-object object");
}

TEST(Grounding, TheObjectOfInterestSettlesWhichOfSeveral) {
  EXPECT_EQ(meaning("the goal is that the mug is in the cupboard", id("mug2")), "goal (in mug2 cupboard1)");
  EXPECT_EQ(meaning("the goal is that the mug is in the cupboard", id("mug1")), "goal (in mug1 cupboard1)");
  EXPECT_EQ(meaning("the goal is that the mug is in the cupboard"), "failure ungrounded-object mug");
  // A bare head names every category it ends: three cans here.
  EXPECT_EQ(meaning("Pick up the can.", id("soda-can1")), "action (pick-up soda-can1 table1)");
  EXPECT_EQ(meaning("Pick up the can."), "failure ungrounded-object can");
}

TEST(Grounding, TheKindsOfPlaceNameEveryPlaceOfThatKind) {
  // The types are receptacle-place and surface-place; the words stay.
  EXPECT_EQ(meaning("Open the receptacle.", id("fridge1")), "action (open fridge1)");
  EXPECT_EQ(meaning("Open the receptacle."), "failure ungrounded-object receptacle");
  EXPECT_EQ(meaning("Put the object on the surface.", id("ketchup1")), "failure ungrounded-object surface");
  ReferenceContext context{world35(), grounder().lexicon(), id("counter1")};
  Resolution r = resolve(NounPhrase{"the", {"surface"}}, Role::kPlace, context);
  ASSERT_TRUE(std::holds_alternative<Reference>(r));
  EXPECT_EQ(std::get<Reference>(r).object, id("counter1"));
  EXPECT_EQ(std::get<Reference>(r).reason, "'surface' is the type surface-place");
}

TEST(Grounding, PickUpDependsOnWhereTheItemIs) {
  EXPECT_EQ(meaning("Pick up the paring-knife."), "action (pick-up-from paring-knife1 dish-rack1)");
  EXPECT_EQ(meaning("Pick up the corkscrew."), "action (pick-up corkscrew1 counter1)");
  EXPECT_EQ(meaning("Pick up glass-tumbler from dish rack"), "action (pick-up-from glass-tumbler2 dish-rack1)");
}

TEST(Grounding, Affordances) {
  EXPECT_EQ(meaning("Close the recycling bin."), "failure affordance-mismatch openable recycling-bin1");
  EXPECT_EQ(meaning("Close the garbage."), "failure affordance-mismatch openable garbage1");
  EXPECT_EQ(meaning("Put the fridge into the drawer."), "failure affordance-mismatch grabbable fridge1");
  EXPECT_EQ(meaning("the goal is that the recycling bin is closed"),
            "failure affordance-mismatch closed recycling-bin1");
  EXPECT_EQ(meaning("the goal is that the recycling bin is open"), "failure affordance-mismatch open recycling-bin1");
  EXPECT_EQ(meaning("the goal is that the ketchup is on the dish rack"),
            "failure affordance-mismatch surface dish-rack1");
  EXPECT_EQ(meaning("Repeat the following tasks while an object is in the table."),
            "failure affordance-mismatch receptacle table1");
}

TEST(Grounding, FailuresCarryASentenceToSay) {
  Interpretation in = grounder().interpret("Close the recycling bin.", world35(), std::nullopt);
  ASSERT_NE(in.failure(), nullptr);
  EXPECT_EQ(in.failure()->message, "The recycling bin has no lid, so it can't be closed.");
  in = grounder().interpret("the goal is that the sink is full of water", world35(), std::nullopt);
  ASSERT_NE(in.failure(), nullptr);
  EXPECT_EQ(in.failure()->kind, FailureKind::kUnknownPredicate);
  EXPECT_EQ(in.failure()->message, "I do not know what it means for the sink to be full of water.");
  in = grounder().interpret("Open the frobnitz.", world35(), std::nullopt);
  ASSERT_NE(in.failure(), nullptr);
  EXPECT_EQ(in.failure()->kind, FailureKind::kUnknownWord);
  EXPECT_EQ(in.failure()->detail, "frobnitz");
}

TEST(Grounding, ReferencesSayHowEachPhraseWasResolved) {
  Interpretation in = grounder().interpret("the goal is that the object is in the trash can and the bin is empty",
                                           world35(), id("paper-cup1"));
  ASSERT_GE(in.references.size(), 2u);
  EXPECT_EQ(in.references[0].method, ReferenceMethod::kObjectOfInterest);
  EXPECT_EQ(in.references[0].object, id("paper-cup1"));
  if (grounder().lexicon().has_wordnet()) {
    EXPECT_EQ(in.references[1].phrase, "trash can");
    EXPECT_EQ(in.references[1].method, ReferenceMethod::kWordNet);
    EXPECT_EQ(in.references[1].object, id("garbage1"));
    EXPECT_FALSE(in.references[1].reason.empty());
  }
  EXPECT_EQ(format_grounding(world35(), in.result), "failure unknown-predicate empty");
}

TEST(Grounding, TheBareHeadBinIsTheRecyclingBin) {
  // The world calls only the recycling bin a bin (docs/language.md).
  EXPECT_EQ(meaning("the goal is that the coke-can is in the bin", id("coke-can1")), "goal (in coke-can1 recycling-bin1)");
}

TEST(Grounding, WithoutWordNetOtherWordsStayUnknown) {
  Grounder plain{Lexicon(std::nullopt)};
  auto say = [&](std::string_view sentence) {
    return format_grounding(world35(), plain.interpret(sentence, world35(), id("paper-cup1")).result);
  };
  EXPECT_EQ(say("the goal is that the paper-cup is in the trashcan"), "failure unknown-word trashcan");
  EXPECT_EQ(say("the goal is that the paper-cup is in the garbage"), "goal (in paper-cup1 garbage1)");
  EXPECT_EQ(say("the goal is that the paper-cup is in the bin"), "goal (in paper-cup1 recycling-bin1)");
}

TEST(Grounding, InterpretGoalAndActionRefuseOtherKinds) {
  const World& world = world35();
  auto goal = grounder().interpret_goal("Open the fridge.", world, std::nullopt);
  ASSERT_NE(goal.failure(), nullptr);
  EXPECT_EQ(goal.failure()->kind, FailureKind::kUninterpretable);
  auto action = grounder().interpret_action("Take the ketchup.", world, std::nullopt);
  ASSERT_NE(action.failure(), nullptr);
  EXPECT_EQ(action.failure()->kind, FailureKind::kUnknownWord);
  EXPECT_EQ(action.failure()->detail, "take");
  auto ok = grounder().interpret_action("Pick up ceramic-plate", world, id("ceramic-plate1"));
  EXPECT_EQ(format_grounding(world, ok.result), "action (pick-up ceramic-plate1 table1)");
}

TEST(Grounding, DescribedObjectBindsTheObject) {
  auto in = grounder().interpret(
      "If the object is a steak-knife then the goal is that the object is in the drawer and the drawer is closed.",
      world35(), id("steak-knife2"));
  EXPECT_EQ(in.bound_object, id("steak-knife2"));
  EXPECT_EQ(format_grounding(world35(), in.result), "goal (and (in steak-knife2 drawer1) (closed drawer1))");
}

TEST(Grounding, CategoryKeys) {
  EXPECT_EQ(category_key("Recycling  Bin"), "recycling-bin");
  EXPECT_EQ(category_key("plastic-bottle"), "plastic-bottle");
  EXPECT_EQ(category_key(""), "");
}

}  // namespace
}  // namespace apprentice::language
