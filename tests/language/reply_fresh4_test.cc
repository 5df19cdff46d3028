// What two more fresh users typed (stop 38, 2026-12-07: a craft room and a
// baby's nursery, docs/fresh-users/craft-room.tsv and nursery.tsv), read
// in the bathroom of tests/language/fresh/set1. Each expectation says what
// the person meant. Checked against the reader before the fixes: the
// verb that names no step, the hurried where-questions, the rule for a
// kind not here and the shorthand failed; the correction after a marker
// and "put ... in" passed at this level, having failed only in a session
// (FreshUsers.TheCraftRoomsNextStepReplies replays the first; the second
// is kept as a guard).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "language/rule_in_reply.h"
#include "language/same_as.h"
#include "language_fixtures.h"
#include "reply_acts_fixture.h"

namespace apprentice::language {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

ReplyContext step_question() {
  ReplyContext step;
  step.asked = Asked::kTaskStep;
  step.taught_subtasks = {"clear"};
  return step;
}

// "ok cool thats all, we're done", after "What should I do with the things
// in the tub?": the task is done, not a part "cool what is in the tub". A
// verb of its own names a part over the places asked about only when it is
// a step verb, near one, or taught.
TEST_F(ReplyActsTest, AVerbThatNamesNoStepIsNoPartOfThePlacesAskedAbout) {
  ReplyContext step = step_question();
  step.topic_places = {id("floor1")};
  EXPECT_EQ(acts(step, "ok cool thats all, we're done"), "finished");
  EXPECT_THAT(acts(step, "cool"), StartsWith("unusable"));
  EXPECT_THAT(acts(step, "skip it"), Not(HasSubstr("subtask")));
  // Step verbs, and verbs near them, still name the part.
  EXPECT_THAT(acts(step, "clear it"), StartsWith("subtask clear"));
  EXPECT_THAT(acts(step, "clear"), StartsWith("subtask clear"));
  EXPECT_THAT(acts(step, "tidy it up"), StartsWith("subtask"));
}

// "no wait, the sketchbook should be on the shelf, its too big for the
// drawer", at the next-step question after the sketchbook went in the
// drawer: a correction, whatever marker comes before it (it was read as
// the part "clear the shelf").
TEST_F(ReplyActsTest, ACorrectionAtTheNextStepMayBeginWithAMarker) {
  ReplyContext step = step_question();
  step.dealt_with = {id("toothbrush1")};
  EXPECT_EQ(acts(step, "no wait, the toothbrush should be on the shelf, its too wet for the drawer"),
            "goal (on toothbrush1 shelf1)");
  EXPECT_EQ(acts(step, "oh actually the toothbrush goes on the shelf"), "goal (on toothbrush1 shelf1)");
}

// "put the diapers that are in the middle drawer in the bottom drawer" puts
// things somewhere: no part "put what is in the middle drawer". "put away"
// may still name one.
TEST_F(ReplyActsTest, PutWithAPlaceIsNoPartOfTheTask) {
  ReplyContext step = step_question();
  EXPECT_THAT(acts(step, "put the towels that are on the floor in the hamper"), Not(HasSubstr("subtask")));
  EXPECT_THAT(acts(step, "put them in the hamper"), Not(HasSubstr("subtask")));
}

// "wheres the pacifier", "where r the diapers": the teacher's question, as
// typed in a hurry.
TEST_F(ReplyActsTest, WhereQuestionsTypedInAHurry) {
  ReplyContext step = step_question();
  EXPECT_EQ(acts(step, "wheres the toothbrush"), "command where toothbrush");
  EXPECT_EQ(acts(step, "where r the towels"), "command where towels");
}

// "oh and fyi ribbons go in the tub too", "no i mean if theres ever ribbon,
// it goes in the tub": where a kind not here goes, at the next-step
// question, is a person's rule of that kind (it was asked back, "What
// should I do with the things in the tub?", or kept as the class "fyi
// ribbons").
TEST_F(ReplyActsTest, ARuleForAKindNotHereIsKeptWithoutItsOpening) {
  const ReplyContext step = step_question();
  for (const char* said : {"oh and fyi ribbons go in the hamper too", "no i mean if theres ever ribbon, it goes in "
                                                                      "the hamper"}) {
    const Reply reply = read_reply(grounder(), world(), step, said);
    auto rule = rule_in_reply(grounder(), world(), said, reply, step);
    ASSERT_TRUE(rule.has_value()) << said << ": " << format_reply(world(), reply);
    ASSERT_EQ(rule->clauses.size(), 1u) << said;
    ASSERT_EQ(rule->clauses.front().classes.size(), 1u) << said;
    EXPECT_THAT(rule->clauses.front().classes.front().head, StartsWith("ribbon")) << said;
    EXPECT_THAT(rule->clauses.front().classes.front().phrase, StartsWith("ribbon")) << said;
  }
  // A part said with the things at a place is still no rule.
  const std::string start = "start with the stuff on the floor";
  const Reply part = read_reply(grounder(), world(), step, start);
  EXPECT_FALSE(rule_in_reply(grounder(), world(), start, part, step).has_value());
}

// "um pencils go w/ the markers": shorthand in "goes with" (it was "I
// didn't catch where the pencil should go", where "with" was read).
TEST(SameAsShorthand, GoesWithSaidInShorthand) {
  EXPECT_EQ(read_same_as("um pencils go w/ the markers").other, "markers");
  EXPECT_EQ(read_same_as("pencils go w the markers").other, "markers");
  EXPECT_EQ(read_same_as("pencils go w/ the markers").subject, "pencils");
}

// "the long tools, rake shovel hoe, they all go on the lower shelf" (a
// fresh user's garden shed): three kinds named one after another without
// commas are a list; only the rake and the shovel were read, and the hoe
// was never put away.
TEST_F(ReplyActsTest, KindsListedWithoutCommasAreAList) {
  ReplyContext c = goal_question("toothbrush1");
  EXPECT_EQ(acts(c, "toothbrush toothpaste comb, they all go on the shelf"),
            "goal (on toothbrush1 shelf1); also (on toothpaste1 shelf1); also (on comb1 shelf1)");
  EXPECT_EQ(acts(c, "toothbrush toothpaste and comb on the shelf"),
            "goal (on toothbrush1 shelf1); also (on toothpaste1 shelf1); also (on comb1 shelf1)");
  EXPECT_EQ(acts(c, "the toothbrush goes on the shelf"), "goal (on toothbrush1 shelf1)");
}

// What a fourth pair of fresh users typed (stop 39: a garage and a laundry
// room, docs/fresh-users/garage.tsv and laundry-room.tsv), read in set 1's
// bathroom. Each failed on the reader before the fix.

// "hamper. close the lid after, the cat gets in there": the answer, its
// closing, and a reason about something not here (it was read as a rule
// that "lid after" and "cat" go in a basket, acted on for three things).
// "the bottom one" still picks a drawer.
TEST_F(ReplyActsTest, AClauseAboutSomethingNotHereAfterAnAnswerIsAReason) {
  ReplyContext c = goal_question("jeans1");
  const std::string text = "hamper. close the lid after, the cat gets in there";
  EXPECT_EQ(acts(c, text), "goal (and (in jeans1 hamper1) (closed hamper1))");
  EXPECT_THAT(notes(c, text), ::testing::Contains(HasSubstr("\"the cat gets in there\" as a reason")));
  EXPECT_FALSE(rule_in_reply(grounder(), world(), text, read_reply(grounder(), world(), c, text), c).has_value());
  EXPECT_EQ(acts(c, "the bottom one"), acts(c, "the bottom drawer"));
}

// Forgetting said along with more, or after a polite frame, is a command;
// "forget that" alone is still never mind.
TEST_F(ReplyActsTest, ForgettingSaidWithMoreIsACommand) {
  ReplyContext c = goal_question("jeans1");
  EXPECT_EQ(acts(c, "hamper. and forget the towel rule"),
            "goal (in jeans1 hamper1) | command forget towel rule");
  ReplyContext step = step_question();
  EXPECT_EQ(acts(step, "ok can you forget that laundry stuff rule, its wrong"), "command forget laundry stuff rule");
  EXPECT_EQ(acts(step, "forget the laundry stuff"), "command forget laundry stuff");
  EXPECT_THAT(acts(step, "forget that, clear the floor"), StartsWith("subtask clear"));
}

// "wait the washer fluid is not recycling, its full! bottom shelf", asked
// about the washer fluid just after the water bottle went in the recycling
// bin: where the thing asked about does not go, and where it does; no
// undo of the water bottle.
TEST_F(ReplyActsTest, APlaceSaidNotOfTheThingAskedIsNoCorrectionOfTheLast) {
  ReplyContext c = goal_question("jeans1", "towel1", "hamper1");
  EXPECT_EQ(acts(c, "wait the jeans are not hamper stuff, theyre clean! top drawer"), "goal (in jeans1 drawer1)");
  // Said of the last thing, it still corrects it.
  EXPECT_THAT(acts(c, "wait the towel is not hamper stuff, top drawer"), StartsWith("command undo"));
}

// "yes. spray bottle in there too", asked whether the fabric softener goes
// in the cabinet just after the detergent went on the lower shelf: "there"
// is the cabinet proposed (it was the lower shelf, named last).
TEST_F(ReplyActsTest, ThereAfterAYesIsThePlaceProposed) {
  ReplyContext c = goal_question("jeans1", "towel1", "shelf1");
  c.asked = Asked::kYesNo;
  c.proposal = Goal({Literal{Fact(world().vocabulary.in, {id("jeans1"), id("hamper1")}), true}});
  c.still_to_come = {id("toothbrush1")};
  const ReplyActs read = read_acts(grounder(), world(), c, "yes. toothbrush in there too");
  ASSERT_EQ(read.acts.size(), 1u);
  const auto* yes = std::get_if<YesNo>(&read.acts.front());
  ASSERT_NE(yes, nullptr) << format_reply(world(), read.acts.front());
  const std::optional<GoalGiven> rest = goal_in_rest(grounder(), world(), c, *yes);
  ASSERT_TRUE(rest.has_value());
  EXPECT_EQ(format_reply(world(), Reply(*rest)), "goal (in toothbrush1 hamper1)");
}

// A door the teacher wants left open from now on, said at any question;
// "leave the cabinet open for now" is this time only.
TEST_F(ReplyActsTest, ADoorLeftOpenFromNowOnIsAStandingWish) {
  ReplyContext step = step_question();
  EXPECT_EQ(acts(step, "leave the hamper open from now on"),
            "command do (open hamper1); left open from now on: hamper1");
  EXPECT_EQ(acts(step, "the hamper should stay open"), "command do (open hamper1); left open from now on: hamper1");
  EXPECT_EQ(acts(step, "dont close the hamper anymore"), "command do (open hamper1); left open from now on: hamper1");
  EXPECT_EQ(acts(step, "leave the hamper open for now"), "command do (open hamper1)");
  ReplyContext c = goal_question("jeans1", "towel1", "hamper1");
  EXPECT_EQ(acts(c, "why is the hamper shut? i want it left open"),
            "command why about hamper1 | command do (open hamper1); left open from now on: hamper1");
  // Said with an answer, "that" is the answer's place (found teaching at
  // the terminal: "filing cabinet, and leave that open from now on" was
  // read without the wish).
  EXPECT_EQ(acts(goal_question("jeans1"), "the cabinet, and leave that open from now on"),
            "goal (in jeans1 cabinet1) | command do (open cabinet1); left open from now on: cabinet1");
}

// Where things go, said after a part of the task, is no further part: it
// is kept for the part's first question (it was "clear the detergent goes
// in the cabinet", a part).
TEST_F(ReplyActsTest, WhereThingsGoSaidAfterAPartIsKeptForItsQuestions) {
  ReplyContext step = step_question();
  const ReplyActs read =
      read_acts(grounder(), world(), step, "clear the counter, the toothbrush goes on the shelf, then the floor");
  ASSERT_EQ(read.acts.size(), 1u);
  EXPECT_EQ(format_reply(world(), read.acts.front()), "subtask clear on counter1");
  EXPECT_EQ(read.then, std::vector<std::string>{"clear the floor"});
  EXPECT_EQ(read.goals_ahead, std::vector<std::string>{"the toothbrush goes on the shelf"});
}

}  // namespace
}  // namespace apprentice::language
