// The agent's sentences in conversation (language/narration_conversation.h):
// status, the teacher's own questions, refused replies and goals said for
// other things, each from the facts the agent passes.
#include "language/narration_conversation.h"

#include <gtest/gtest.h>

#include "language/generation.h"
#include "language/narration_steps.h"
#include "language/narration_summary.h"

#include "language_fixtures.h"

namespace apprentice::language {
namespace {

using testing::kitchen30;

ObjectId thing(std::string_view name) { return *kitchen30().world.universe->find(name); }

SubtaskUnderWay clearing_the_table() { return {"clear", "on", {thing("table1")}}; }

TEST(NarrationConversation, StatusSaysTheTaskThePartAndWhatIsKnown) {
  const World& w = kitchen30().world;
  WhatIAmDoing doing;
  EXPECT_EQ(what_i_am_doing(w, doing),
            "I have not been given a task yet. So far I know 0 goals and 0 rules, after 0 instructions this session.");
  doing.task = "tidy kitchen";
  doing.subtask = clearing_the_table();
  doing.working_on = thing("ketchup1");
  doing.asking_about = thing("milk1");  // working on something comes first
  doing.goals = 3;
  doing.rules = 1;
  doing.instructions = 1;
  EXPECT_EQ(what_i_am_doing(w, doing),
            "I am learning to tidy the kitchen; now I clear what is on the table, working on the ketchup. So far I "
            "know 3 goals and 1 rule, after 1 instruction this session.");
  doing.working_on.reset();
  EXPECT_NE(what_i_am_doing(w, doing).find(", asking about the milk."), std::string::npos);
}

// Found by a fresh user: "Does the headphones on the chair go ...: it goes
// ...?". A thing named in the plural takes "do" and "they".
TEST(NarrationConversation, AProposalAgreesWithAThingNamedInThePlural) {
  const World& w = kitchen30().world;
  const Goal in_pantry({Literal{Fact(w.vocabulary.in, {thing("crackers1"), thing("pantry1")}), true}});
  EXPECT_EQ(ask_goal_proposed(w, thing("crackers1"), in_pantry, "like the cereal", {}),
            "Do the crackers on the counter go like the cereal: they go in the pantry?");
  // What `run` would have done, and where it needs help, agree with a
  // plural name too (a fresh user read "where the sunglasses ... goes").
  EXPECT_EQ(not_sure_enough(w, thing("crackers1"), in_pantry, "like the cereal", "0.63"),
            "it may be that they go in the pantry, like the cereal, but I am not sure enough (confidence 0.63)");
  EXPECT_EQ(help_needed_for_goal(w, thing("crackers1"), "store", {}), "where the crackers on the counter go (store)");
  EXPECT_EQ(help_needed_for_goal(w, thing("ketchup1"), "clear", {}), "where the ketchup on the table goes (clear)");
  const Goal in_fridge({Literal{Fact(w.vocabulary.in, {thing("ketchup1"), thing("fridge1")}), true}});
  EXPECT_EQ(ask_goal_proposed(w, thing("ketchup1"), in_fridge, "", {}),
            "Does the ketchup on the table go here: it goes in the fridge?");
}

TEST(NarrationConversation, WhatIsLeftOfAPartCountsTheThingsThere) {
  const World& w = kitchen30().world;
  EXPECT_EQ(whats_left_of_subtask(w, clearing_the_table(), {}), "Nothing else is left on the table.");
  const std::vector<ObjectId> left = {thing("ketchup1"), thing("milk1")};
  EXPECT_EQ(whats_left_of_subtask(w, clearing_the_table(), left), "Still on the table: the ketchup and the milk.");
}

TEST(NarrationConversation, WhereThingsAreSaysEachOrWhyNot) {
  const World& w = kitchen30().world;
  EXPECT_EQ(where_things_are(w, "the unicorn", {}), std::vector<std::string>{"I don't see a unicorn here."});
  const std::vector<ObjectId> ketchup = {thing("ketchup1")};
  EXPECT_EQ(where_things_are(w, "the ketchup", ketchup), std::vector<std::string>{"The ketchup is on the table."});
  // At most three things are said, however many the phrase named.
  std::vector<ObjectId> many;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem)) many.push_back(o);
  ASSERT_GT(many.size(), 3u);
  EXPECT_EQ(where_things_are(w, "everything", many).size(), 3u);
  // "where is that now": no thing named, asked back by name (it was "I
  // don't see a  here.").
  const std::vector<std::string> that = where_things_are(w, "that", {});
  ASSERT_EQ(that.size(), 1u);
  EXPECT_THAT(that.front(), ::testing::StartsWith("Which thing do you mean? Name it, for example \"where is the "));
}

// Two things of one kind at one place are said once (a fresh user's
// "where'd the sneakers end up" got "The sneaker is in the locker." twice).
TEST(NarrationConversation, ThingsOfOneKindAtOnePlaceAreSaidTogether) {
  const World& w = kitchen30().world;
  std::vector<ObjectId> pair;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (w.universe->with_category(w.universe->info(o).category).size() == 2 &&
        place_of(w, o) == place_of(w, w.universe->with_category(w.universe->info(o).category).back()))
      pair.push_back(o);
  if (pair.empty()) GTEST_SKIP() << "the kitchen has no two things of one kind at one place";
  const std::string kind = w.universe->info(pair.front()).category;
  std::vector<ObjectId> both(w.universe->with_category(kind).begin(), w.universe->with_category(kind).end());
  const std::vector<std::string> said = where_things_are(w, kind, both);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_THAT(said.front(), ::testing::StartsWith("Both ")) << said.front();
}

TEST(NarrationConversation, ARefusedReplyEndsInOnePeriodAndOffersTwoExamples) {
  EXPECT_EQ(reply_refused("I asked what to do next", {"open the fridge", "pick up the ketchup", "close it"}),
            "I asked what to do next. You could say, for example, \"open the fridge\" or \"pick up the ketchup\".");
  EXPECT_EQ(reply_refused("Which one?", {}), "Which one?");
  // A quotation that ends with its own period gets none after it.
  EXPECT_EQ(with_period("You said \"Clear the table.\""), "You said \"Clear the table.\"");
  EXPECT_EQ(kinds_of_answer(Asked::kYesNo, {}), "Answer yes or no.");
  EXPECT_EQ(kinds_of_answer(Asked::kAction, {"open the fridge"}), "Tell me one thing to do next, for example \"open the fridge\".");
}

TEST(NarrationConversation, GoalsForOtherThingsUseTheRightPronoun) {
  const World& w = kitchen30().world;
  const std::vector<ObjectId> fork = {thing("metal-fork1")}, two = {thing("metal-fork1"), thing("ketchup1")};
  EXPECT_EQ(goals_for_others(w, fork, fork, {}),
            std::vector<std::string>{"The same goes for the metal fork, when I come to it."});
  EXPECT_EQ(goals_for_others(w, {}, two, {}), std::vector<std::string>{"I will do that when I come to them."});
  EXPECT_EQ(goals_for_others(w, {}, {}, fork),
            std::vector<std::string>{"I will ask about the metal fork when I come to it."});
  EXPECT_TRUE(goals_for_others(w, {}, {}, {}).empty());
}

TEST(NarrationConversation, ForgettingNamesTheKind) {
  EXPECT_EQ(forgot_where_kind_goes("glass-tumbler"), "I forgot where the glass tumbler goes; I will ask when I meet one.");
  EXPECT_EQ(nothing_to_forget(std::nullopt, "  the unicorns "),
            "I have not learned where to put the unicorns, so there is nothing to forget.");
  EXPECT_EQ(which_kind_to_forget({"red-cup", "blue-cup"}),
            "Which kind do you mean: the red cup and the blue cup? Say, for example, \"forget red cup\".");
}

}  // namespace

// Each thing `run` would need help with is said once, with a count when
// several things need the same ("the bulb" three times).
TEST(NarrationSummary, TheSameHelpIsSaidOnceWithACount) {
  PerformanceEnd how;
  how.help_needed = {"where the bulb on the bench goes (clear)", "where the spade on the floor goes (clear)",
                     "where the bulb on the bench goes (clear)", "where the bulb on the bench goes (clear)"};
  const std::string said = performance_summary(how);
  EXPECT_NE(said.find("Would need help: where the bulb on the bench goes (clear) (3 of them)\n"
                      "Would need help: where the spade on the floor goes (clear)\n"),
            std::string::npos)
      << said;
}

}  // namespace apprentice::language
