// The fifth and sixth pairs of fresh users (stop 40, 2026-12-08). The fifth
// taught a living room
// and a home gym of their own (tests/agent/data/fresh-users/livingroom*.yaml
// and gym*.yaml) with `apprentice teach` in a terminal, having read only the
// README and the docs. Of 139 replies, 98 were understood and 19 acted on
// wrongly (docs/fresh-users/living-room.tsv, home-gym.tsv). Each test types
// replies like theirs into the real binary and asserts what a person meant;
// each failed on the code before its fix. The sixth pair (a teenager's
// bedroom, a shop stockroom: bedroom*.yaml, stockroom*.yaml) taught on the
// fixed program: 140 replies, 31 wrong (docs/fresh-users/teen-bedroom.tsv,
// stockroom.tsv); the tests for what was fixed of theirs are last.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fresh_users_fixture.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class FreshUsersFifthPair : public testing::FreshUserTeaching {};

// The gym's bench, taught as its teacher might, with a "Which hook?" the
// teacher first declines.
std::vector<std::string> gym_bench() {
  return {"tidy the gym", "clear the bench first", "hamper", "top shelf", "top shelf", "put it on a hook",
          "skip it",      "left hook",            "trash",  "locker"};
}

// "skip it", asked which hook: the reply the question came from is set
// aside and its question asked again. Before: "None of them is "skip it"",
// and the hook question for ever.
TEST_F(FreshUsersFifthPair, AWhichQuestionCanBeDeclined) {
  const std::string out = teach("gym.yaml", gym_bench());
  EXPECT_THAT(out, HasSubstr("Instructor: skip it\nAgent: Then I leave \"put it on a hook\" aside."));
  EXPECT_THAT(out, HasSubstr("Agent: Where should the jump rope on the bench go?\nInstructor: left hook\n"
                             "Agent: So the jump rope goes on the left hook.\n"))
      << out;
}

// "no wait put it back, it leaks. shelf was right", after a correction
// moved the water bottle into the locker. Before: a part "put back what is
// on the shelves", and the bottle stayed in the locker.
TEST_F(FreshUsersFifthPair, PuttingItBackUndoesTheCorrection) {
  std::vector<std::string> replies = gym_bench();
  replies.insert(replies.end(), {"actually the water bottle goes in the locker",
                                 "no wait put it back, it leaks. shelf was right", "where is the water bottle?", "quit"});
  const std::string out = teach("gym.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Instructor: no wait put it back, it leaks. shelf was right\n"
                             "Agent: I took \"it leaks\" as a reason, not an instruction.\n"
                             "Agent: I forgot what you told me last: \"actually the water bottle goes in the locker\".\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: where is the water bottle?\nAgent: The water bottle is on the top shelf.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("put back what"))) << out;
}

std::vector<std::string> living_room_coffee_table() {
  return {"tidy the living room", "clear the coffee table", "tray", "top drawer", "magazine rack",
          "candle in the cabinet, chip bag is trash"};
}

// "the top drawer should stay open from now on" is about the top drawer:
// the bottom drawer is still closed after the candle goes in. Before: the
// wish was kept for every drawer, and the bottom one was left open.
TEST_F(FreshUsersFifthPair, ADoorLeftOpenIsThatDoorNotItsLookAlike) {
  std::vector<std::string> replies = living_room_coffee_table();
  replies.insert(replies.end(), {"the top drawer should stay open from now on",
                                 "actually the candle goes in the bottom drawer", "quit"});
  const std::string out = teach("livingroom.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Agent: I will leave the top drawer open from now on")) << out;
  EXPECT_THAT(out, HasSubstr("Agent: So the candle goes in the bottom drawer, and the bottom drawer ends closed.\n"))
      << out;
}

// "the blanket goes on the sofa, its cold tonight": moved, not learned.
// Before: learned as the blanket's place for good, said nowhere.
TEST_F(FreshUsersFifthPair, APlaceForTonightIsNotLearned) {
  const std::string out = teach("livingroom.yaml", {"tidy the living room", "clear the sofa", "basket",
                                                    "the blanket goes on the sofa, its cold tonight",
                                                    "socks go in the hamper", "top shelf",
                                                    "why is the blanket on the sofa?", "quit"});
  EXPECT_THAT(out, HasSubstr("Agent: I took \"tonight\" as this time only.\n"
                             "Agent: So the blanket goes on the sofa. This time only: I will not remember it as where "
                             "that goes.\n"
                             "Agent: I took the blanket out of the basket and put it on the sofa.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: You told me to put the blanket there this time only.")) << out;
  // The sofa's part ends without the blanket counted as left over.
  EXPECT_THAT(out, Not(HasSubstr("could not clear"))) << out;
  // Taught again, the blanket's place is still the basket.
  const std::string again = teach("livingroom.yaml", {"tidy the living room", "quit"});
  EXPECT_THAT(again, HasSubstr("Agent: Next, the blanket on the sofa: it goes in the basket.\n"
                               "Agent: I put the blanket in the basket.\n"))
      << again;
}

// "newspapers dont go in ..., they go in ..." and "slippers by the door
// on the shoe rack pls". Before: a rule that newspapers go where they do
// not, for a class "newspapers do not", and a class "slippers by the door".
TEST_F(FreshUsersFifthPair, WhereThingsDoNotGoAndWhereTheyAreNameNoClass) {
  std::vector<std::string> replies = living_room_coffee_table();
  replies.insert(replies.end(), {"now clear the floor",
                                 "newspapers dont go in the toy box, they go in the magazine rack. toys go in the toy box",
                                 "quit"});
  const std::string out = teach("livingroom.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Agent: So newspapers go in the magazine rack and toys go in the toy box.\n")) << out;
  EXPECT_THAT(out, Not(HasSubstr("do not go"))) << out;
  const std::string slippers = teach("livingroom.yaml", {"tidy the living room", "clear the floor",
                                                         "slippers by the door on the shoe rack pls", "quit"});
  EXPECT_THAT(slippers, HasSubstr("Agent: So slippers go on the shoe rack.\n")) << slippers;
  EXPECT_THAT(slippers, Not(HasSubstr("slippers by the door go"))) << slippers;
}

// "shut the locker. this one stays closed, my brothers cat gets in there",
// after the locker was to be left open: the wish is kept, and a goal into
// the locker learned after closes it. Before: closed now, and the next
// thing put in the locker left it open.
TEST_F(FreshUsersFifthPair, ADoorToStayClosedIsAStandingWish) {
  std::vector<std::string> replies = gym_bench();
  replies.insert(replies.end(), {"leave the locker open from now on",
                                 "shut the locker. this one stays closed, my brothers cat gets in there",
                                 "actually the water bottle goes in the locker", "quit"});
  const std::string out = teach("gym.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Agent: I closed the locker.\n"
                             "Agent: I will close the locker from now on, also after putting the headphones in it.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: So the water bottle goes in the locker, and the locker ends closed.\n")) << out;
  EXPECT_THAT(out, Not(HasSubstr("already closed"))) << out;
}

// "why did you put the towel on the hook before?", with a clean towel and
// a dirty one, after the dirty one's place was corrected; "ok but why the
// hook at first". Before: the clean towel's goal of now, and a part "clear
// the left hook".
TEST_F(FreshUsersFifthPair, WhyBeforeIsAboutTheTowelThatWentOnTheHook) {
  const std::string out =
      teach("gym.yaml", {"tidy the gym", "clear the bench first", "right hook", "top shelf", "top shelf", "left hook",
                         "trash", "locker", "actually the dirty towel goes in the hamper",
                         "why did you put the towel on the hook before?", "ok but why the hook at first", "quit"});
  const std::string earlier = "Agent: Earlier I decided the dirty towel goes on the right hook, as you told me then; "
                              "since then, the dirty towel goes in the hamper.\n";
  EXPECT_THAT(out, HasSubstr("Instructor: why did you put the towel on the hook before?\n" + earlier)) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: ok but why the hook at first\n" + earlier)) << out;
}

// "straighten up my office" in a home office: the room is the office, and
// "straighten up" is tidying, said so. Before: a task "straighten office".
TEST_F(FreshUsersFifthPair, TheLastWordOfTheRoomsNameIsTheRoom) {
  const std::string out = teach("office2.yaml", {"hey can you straighten up my office", "quit"});
  EXPECT_THAT(out, HasSubstr("Agent: I took \"straighten up\" as tidying.\n"
                             "Agent: What should I do first to tidy the home office?\n"))
      << out;
}

// "nah not trash, cables and chargers and stuff go in the top drawer" made a
// rule that trash goes in the top drawer, and "forget trash in the top
// drawer" then forgot "the drawer". A class said not to be meant is none,
// and a rule is forgotten by its class and place.
TEST_F(FreshUsersFifthPair, ARuleSaidWithANotIsForgottenByItsWords) {
  const std::string out = teach("bedroom2.yaml", {"tidy the bedroom",
                                                  "nah not trash, cables and chargers and stuff go in the top drawer",
                                                  "forget cables in the top drawer", "quit"});
  EXPECT_THAT(out, HasSubstr("Agent: So cables, chargers and stuff go in the top drawer.\n")) << out;
  EXPECT_THAT(out, HasSubstr("Agent: I forgot that cables go in the top drawer")) << out;
  EXPECT_THAT(out, Not(HasSubstr("So trash"))) << out;
  EXPECT_THAT(out, Not(HasSubstr("where to put the drawer"))) << out;
}

}  // namespace
}  // namespace apprentice
