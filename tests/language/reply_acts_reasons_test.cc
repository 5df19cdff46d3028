// read_acts on what set 8's writers said around their answers (found on
// its first run, 2026-12-07): why, told after the answer; what someone
// did, told after a one-off action; the thing asked about left by name;
// "knife too"; a look-alike's property said after its name or as a
// comparative; a place alone as the first part. Every expectation was
// written from what a person means, before the reading was run on it.
#include <gtest/gtest.h>

#include "fresh_corpus.h"
#include "language/reply.h"
#include "language_fixtures.h"
#include "reply_acts_fixture.h"

namespace apprentice::language {
namespace {

bool noted(const std::vector<std::string>& notes, std::string_view part) {
  for (const std::string& n : notes)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

// "leave the lid open, more stuff is going in", "leave it open so I can
// grab it in the dark": why is no instruction; the answer stands, and the
// read-back says how the reason was taken.
TEST_F(ReplyActsTest, AReasonToldAfterTheAnswerIsNoInstruction) {
  ReplyContext c = goal_question("towel1");
  const std::string open_hamper = "goal (and (in towel1 hamper1) (not (closed hamper1)))";
  EXPECT_EQ(acts(c, "hamper, and leave the lid open"), open_hamper);
  EXPECT_EQ(acts(c, "hamper, and leave the lid open, more stuff is going in"), open_hamper);
  EXPECT_EQ(acts(c, "hamper. leave it open, I still need to put stuff in there"), open_hamper);
  EXPECT_EQ(acts(c, "hamper and leave it open so I can add the rest later"), open_hamper);
  EXPECT_TRUE(noted(notes(c, "hamper, and leave the lid open, more stuff is going in"), "as a reason"));
  // A clause that says where a thing goes is no reason.
  EXPECT_EQ(acts(c, "hamper, it goes in the hamper"), "goal (in towel1 hamper1)");
  // "ok so I want you to ...": "so" after fillers begins the reply.
  ReplyContext task;
  task.asked = Asked::kTask;
  EXPECT_EQ(acts(task, "ok so I want you to tidy up the bathroom"), "task tidy bathroom");
  // Asked whether a part has more, "there's still stuff on it" is the answer.
  ReplyContext more;
  more.asked = Asked::kSubtaskEnd;
  EXPECT_EQ(acts(more, "yep, there's still stuff on it"), acts(more, "there's still stuff on it"));
  EXPECT_NE(acts(more, "there's still stuff on it"), "unusable");
}

// "close the icebox someone left it open", "oh and close the cabinet,
// someone left it open": the action is done; what someone did is told.
TEST_F(ReplyActsTest, WhatSomeoneDidToldAfterAnActionLeavesTheActionWhole) {
  ReplyContext c = goal_question("toothbrush1");
  EXPECT_EQ(acts(c, "top drawer. also close the cabinet pls someone left it open"),
            "goal (in toothbrush1 drawer1) | command do (close cabinet1)");
  EXPECT_EQ(acts(c, "top drawer, and close the cabinet, someone left it open"),
            "goal (in toothbrush1 drawer1) | command do (close cabinet1)");
  // At a yes/no question, a yes said with a word that is also a filler.
  ReplyContext asked = goal_question("comb1");
  asked.asked = Asked::kYesNo;
  asked.proposal = Goal({Literal{Fact(world().vocabulary.in, {id("comb1"), id("drawer1")}), true}});
  EXPECT_EQ(acts(asked, "yeah. oh and close the cabinet, someone left it open"), "yes | command do (close cabinet1)");
  EXPECT_EQ(acts(asked, "yeah that's right"), "yes");
}

// "first shut the cabinet... no wait it's already shut. just clear the
// counter": the action said before the correction is taken back.
TEST_F(ReplyActsTest, AnActionTakenBackInTheReplyIsNotDone) {
  ReplyContext step;
  step.asked = Asked::kTaskStep;
  EXPECT_EQ(acts(step, "first shut the cabinet, then clear the counter"), "command do (close cabinet1)");
  EXPECT_EQ(read_acts(grounder(), world(), step, "first shut the cabinet, then clear the counter").then,
            std::vector<std::string>{"clear the counter"});
  EXPECT_EQ(acts(step, "first shut the cabinet... no wait it's already shut. just clear the counter"),
            "subtask clear on counter1");
}

// "leave the sweater", "leave the notebook out", asked about it: left.
TEST_F(ReplyActsTest, TheThingAskedAboutLeftByNameIsLeft) {
  ReplyContext c = goal_question("hair-dryer1");
  EXPECT_EQ(acts(c, "leave the hair dryer"), "finished");
  EXPECT_EQ(acts(c, "leave the hair dryer out, I still need it"), "finished");
  // Where it is to be left is a goal; another thing named is not this one.
  EXPECT_EQ(acts(c, "leave the hair dryer in the cabinet"), "goal (in hair-dryer1 cabinet1)");
  EXPECT_NE(acts(c, "leave the razor"), "finished");
}

// "pan in the sink, knife too": the things said "too" after the answer go
// where it goes. With several places said, which one "too" repeats is not
// guessed.
TEST_F(ReplyActsTest, ThingsSaidTooAfterTheAnswerGoTheSamePlace) {
  ReplyContext c = goal_question("toothbrush1");
  c.still_to_come = {id("toothpaste1"), id("comb1")};
  EXPECT_EQ(acts(c, "top drawer, toothpaste too"), "goal (in toothbrush1 drawer1); also (in toothpaste1 drawer1)");
  EXPECT_EQ(acts(c, "in the top drawer and the toothpaste as well"),
            "goal (in toothbrush1 drawer1); also (in toothpaste1 drawer1)");
  const std::string several = acts(c, "toothbrush in the top drawer, comb in the bottom drawer, toothpaste too");
  EXPECT_EQ(several.find("(in toothpaste1 drawer1)"), std::string::npos) << several;
}

// "lower drawer", "the drawer on the bottom", "the drawer up top": a
// look-alike's property said as a comparative, or after the name.
TEST_F(ReplyActsTest, ALookAlikesPropertySaidAfterItsNameOrAsAComparativeNamesIt) {
  ReplyContext c = goal_question("razor1");
  EXPECT_EQ(acts(c, "lower drawer"), "goal (in razor1 drawer2)");
  EXPECT_EQ(acts(c, "upper drawer"), "goal (in razor1 drawer1)");
  EXPECT_EQ(acts(c, "the drawer on the bottom"), "goal (in razor1 drawer2)");
  EXPECT_EQ(acts(c, "in the drawer up top"), "goal (in razor1 drawer1)");
  // "on the top shelf" names no look-alike's property after a name.
  EXPECT_NE(acts(c, "drawer on the shelf"), "goal (in razor1 drawer1)");
}

// A world whose look-alikes are told apart by "upper" and "lower": "bottom
// cupboard" is the lower one.
TEST(ReplyActsLookAlikes, APropertySaidInItsOwnWordsOrAnothersIsTheSame) {
  fresh::Worlds worlds(testing::source_path("tests/language/fresh/set8"));
  std::string error;
  const Scenario* vet = worlds.get("vet-exam-room.yaml", error);
  ASSERT_NE(vet, nullptr) << error;
  const World& w = vet->world;
  ReplyContext c;
  c.asked = Asked::kGoal;
  c.object = w.universe->find("muzzle1");
  ASSERT_TRUE(c.object.has_value());
  const ObjectId lower = *w.universe->find("cabinet2");
  ASSERT_EQ(w.universe->info(lower).properties, std::vector<std::string>{"lower"});
  for (const char* said : {"bottom cabinet", "the bottom cupboard", "in the lower cabinet"}) {
    const std::string read = format_reply(w, read_acts(grounder(), w, c, said).acts.front());
    EXPECT_EQ(read, "goal (in muzzle1 " + w.universe->name(lower) + ")") << said;
  }
}

// "sharps bin", "rubbish bin": a container word said after words that
// name one receptacle here is that receptacle, and "bin" there is no verb;
// "bin it" still throws the thing away.
TEST(ReplyActsContainerWords, AContainerWordAfterWhatNamesAReceptacleIsThatReceptacle) {
  fresh::Worlds worlds(testing::source_path("tests/language/fresh/set8"));
  std::string error;
  auto goal_read = [&](const char* file, const char* about, const char* said) {
    const Scenario* scenario = worlds.get(file, error);
    if (scenario == nullptr) return "no world: " + error;
    const World& w = scenario->world;
    ReplyContext c;
    c.asked = Asked::kGoal;
    c.object = w.universe->find(about);
    if (!c.object) return std::string("no ") + about;
    ReplyActs read = read_acts(grounder(), w, c, said);
    return read.acts.empty() ? std::string("nothing") : format_reply(w, read.acts.front());
  };
  EXPECT_EQ(goal_read("vet-exam-room.yaml", "syringe1", "sharps bin"), "goal (in syringe1 sharps-container1)");
  EXPECT_EQ(goal_read("vet-exam-room.yaml", "syringe1", "in the sharps bin please"),
            "goal (in syringe1 sharps-container1)");
  EXPECT_EQ(goal_read("vet-exam-room.yaml", "glove1", "rubbish bin"), "goal (in glove1 trash-can1)");
  // The maker space has a scrap bin too, and WordNet's rubbish is scrap:
  // which one is asked, never taken.
  EXPECT_EQ(goal_read("maker-space.yaml", "coffee-cup1", "in the rubbish bin").rfind("ambiguous", 0), 0u);
  EXPECT_EQ(goal_read("maker-space.yaml", "coffee-cup1", "just bin it"), "goal (in coffee-cup1 trash-can1)");
  // A word naming no receptacle before "bin" names nothing by it.
  EXPECT_NE(goal_read("vet-exam-room.yaml", "syringe1", "stethoscope bin"), "goal (in syringe1 sharps-container1)");
}

// Before any part is taught, "the counter, clear it and then we're done":
// one part, said twice, then the ending for the next question.
TEST_F(ReplyActsTest, APartNamedThenSaidAgainIsOnePart) {
  ReplyContext step;
  step.asked = Asked::kTaskStep;
  ReplyActs read = read_acts(grounder(), world(), step, "and now the counter, clear it and then we're done");
  ASSERT_EQ(read.acts.size(), 1u);
  EXPECT_EQ(format_reply(world(), read.acts.front()), "subtask clear on counter1");
  EXPECT_EQ(read.then, std::vector<std::string>{"we are done"});
  EXPECT_TRUE(read_acts(grounder(), world(), step, "the floor. get all that junk off the floor").then.empty());
}

}  // namespace
}  // namespace apprentice::language
