// Two fresh users taught rooms of their own on 2026-12-07 (stop 37), with
// `apprentice teach` in a terminal, after reading only the README and the
// docs: a mudroom and a dorm room (tests/agent/data/fresh-users, their own
// worlds). Of 107 replies, 18 were acted on wrongly. Each test here types
// the replies that went wrong, as they typed them, into the real binary,
// and asserts what a person meant. Each failed on the code before the fix.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fresh_users_fixture.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class FreshUsers : public testing::FreshUserTeaching {};

// The mudroom's first parts, as its teacher taught them.
std::vector<std::string> mudroom_start() {
  return {"ugh the mudroom is a disaster again, can you help me tidy it up",
          "well start with the stuff on the floor i guess",
          "shoes go in the shoe cabinet, boots too",
          "hmm hang it on the bottom hook",
          "now the bench",
          "coats and jackets go on the top hooks, scarf in the left basket, gloves in the right one",
          "its a coat?? top hooks",
          "helmet on the shelf",
          "leash goes on the top hook"};
}

// A thing put away, corrected at the question about the task's next step,
// named by the last word of its name ("the leash" for the dog leash), with
// a marker before and a reason after; and "move X to Y". Before: "So I
// clear what is on the bottom hook rack, one thing at a time."
TEST_F(FreshUsers, ACorrectionNamesTheThingByPartOfItsName) {
  std::vector<std::string> replies = mudroom_start();
  replies.insert(replies.end(), {"no wait, actually the leash goes on the bottom hook, the kids cant reach the top",
                                 "move the helmet to the left basket", "that's all"});
  const std::string out = teach("mudroom.yaml", replies);
  EXPECT_THAT(out, HasSubstr("the kids cant reach the top\nAgent: I left out \"no wait\": you corrected it.\n"
                             "Agent: So the dog leash goes on the bottom hook rack.\n"
                             "Agent: I put the dog leash on the bottom hook rack.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: move the helmet to the left basket\n"
                             "Agent: So the bike helmet goes in the left basket.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("So I clear what is on the bottom hook rack"))) << out;
  EXPECT_THAT(out, Not(HasSubstr("What should I do with the things in the left basket"))) << out;
}

// One-off doors at the next-step question, said with "leave ... open",
// "should be closed", a marker or a reason; and an ending with one. Before:
// "So I leave what is in the shoe cabinet, one thing at a time."
TEST_F(FreshUsers, OneOffDoorsAreDoneNotMadePartsOfTheTask) {
  std::vector<std::string> replies = mudroom_start();
  replies.insert(replies.end(), {"open the shoe cabinet and leave it open, it needs to air out", "close it",
                                 "hmm ok actually close the shoe cabinet, my roommate hates when its open",
                                 "the shoe cabinet should be open", "thats all, leave the cabinet open"});
  const std::string out = teach("mudroom.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Instructor: open the shoe cabinet and leave it open, it needs to air out\n"
                             "Agent: I took \"it needs to air out\" as a reason, not an instruction.\n"
                             "Agent: I opened the shoe cabinet.\n"))
      << out;
  // "it": the place of the one-off action before.
  EXPECT_THAT(out, HasSubstr("Instructor: close it\nAgent: I closed the shoe cabinet.\n")) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: hmm ok actually close the shoe cabinet, my roommate hates when its open\n"
                             "Agent: I took \"my roommate hates when its open\" as a reason, not an instruction.\n"
                             "Agent: The shoe cabinet is already closed.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: the shoe cabinet should be open\nAgent: I opened the shoe cabinet.\n")) << out;
  // The ending ends the task; the cabinet is already open as asked.
  EXPECT_THAT(out, HasSubstr("Instructor: thats all, leave the cabinet open\n"
                             "Agent: The shoe cabinet is already open.\nAgent: So the task is done.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("So I leave what is"))) << out;
}

// "why ...?" about a thing or a door named is answered about it, not about
// the last reply. Before: "Because of what you told me last: ..." about the
// umbrella, asked about the gloves.
TEST_F(FreshUsers, WhyAboutAThingOrADoorNamedIsAnsweredAboutIt) {
  std::vector<std::string> replies = mudroom_start();
  replies.insert(replies.end(), {"ok now the table by the door", "keys in the bowl obviously",
                                 "thats just junk mail, recycle it. newspaper too",
                                 "umbrella goes in the closet but leave the closet open so it can dry",
                                 "hmm why did you put the glove in the right basket", "why is the closet still open?",
                                 "why did you put the key in the bowl", "that's all"});
  const std::string out = teach("mudroom.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Instructor: hmm why did you put the glove in the right basket\n"
                             "Agent: The glove goes in the right basket: I learned that from the instructor, who said "
                             "\"coats and jackets go on the top hooks, scarf in the left basket, gloves in the right "
                             "one\"."))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: why is the closet still open?\n"
                             "Agent: The closet is open because the umbrella goes there with it left open; I learned "
                             "that from the instructor, who said \"umbrella goes in the closet but leave the closet "
                             "open so it can dry\". Say \"close the closet\" to close it now.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: why did you put the key in the bowl\nAgent: The key goes in the key bowl: "))
      << out;
}

// A door left open for one kind ("so it can dry") is that kind's
// exception: the next kind put in the closet has it closed after, by the
// norm. Before: the flashlight left the closet open, and the read-back
// said nothing of the door.
TEST_F(FreshUsers, ADoorLeftOpenForOneKindIsClosedForTheNext) {
  std::vector<std::string> first = mudroom_start();
  first.insert(first.end(), {"ok now the table by the door", "keys in the bowl obviously",
                             "thats just junk mail, recycle it. newspaper too",
                             "umbrella goes in the closet but leave the closet open so it can dry", "that's all"});
  const std::string taught = teach("mudroom.yaml", first);
  ASSERT_THAT(taught, HasSubstr("So the umbrella goes in the closet, and the closet ends open.")) << taught;
  const std::string out = teach("mudroom2.yaml", {"tidy the mudroom", "right basket", "shelf", "yes", "left basket",
                                                  "key bowl", "flashlight in the closet, sunglasses too", "no",
                                                  "that's all"});
  EXPECT_THAT(out, HasSubstr("Instructor: flashlight in the closet, sunglasses too\n"
                             "Agent: So the flashlight goes in the closet, and the closet ends closed."))
      << out;
  EXPECT_THAT(out, HasSubstr("put the flashlight in it, and closed it.")) << out;
}

// The dorm room: a rule said with a "no" to a proposal answers it, and
// "put the lid back on after" is no class going in the basket. Before: "I
// did not follow "lol no"", the same proposal again, and the rule "lid
// goes in the laundry basket"; then (until stop 38) "Where should the
// textbook on the desk go?", as if the rule said with the "no" did not
// place the textbook, a published work and so a book.
TEST_F(FreshUsers, ARuleSaidWithANoAnswersTheProposal) {
  const std::string out =
      teach("dorm.yaml", {"ok so my room is a disaster after finals, can you help me clean it up",
                          "um start with the floor i guess, pick everything up",
                          "all the dirty clothes go in the laundry basket, put the lid back on after",
                          "no, shoes go in the wardrobe", "the desk next",
                          "lol no. books and notebooks go on the shelf and trash goes in the wastebasket"});
  EXPECT_THAT(out, Not(HasSubstr("lid goes in"))) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: lol no. books and notebooks go on the shelf and trash goes in the "
                             "wastebasket\nAgent: So books and notebooks go on the bookshelf and trash goes in the "
                             "wastebasket.\nAgent: The textbook on the desk goes on the bookshelf, with books, as you "
                             "said.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("Where should the textbook"))) << out;
  EXPECT_THAT(out, Not(HasSubstr("I did not follow \"lol no\""))) << out;
}

// At the next-step question "forget it" and "wait" are no parts, and "i'm
// done, thanks" ends the task. Before: "So I forget what is in the
// wardrobe", "So I clear what is in the wardrobe".
TEST_F(FreshUsers, NeverMindAndEndingsAtTheNextStepAreNoParts) {
  const std::string out =
      teach("dorm.yaml", {"ok so my room is a disaster after finals, can you help me clean it up",
                          "um start with the floor i guess, pick everything up",
                          "all the dirty clothes go in the laundry basket, put the lid back on after",
                          "no, shoes go in the wardrobe",
                          "ok forget it. the sneaker goes in the wardrobe and close it",
                          "oh wait, the towel goes on the bed not in the basket, its clean", "ok i'm done, thanks"});
  EXPECT_THAT(out, HasSubstr("Instructor: ok forget it. the sneaker goes in the wardrobe and close it\n"
                             "Agent: I took \"ok forget it\" as never mind.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: oh wait, the towel goes on the bed not in the basket, its clean\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("So the towel goes on the bed.")) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: ok i'm done, thanks\nAgent: So the task is done.")) << out;
  EXPECT_THAT(out, Not(HasSubstr("So I forget what"))) << out;
  EXPECT_THAT(out, Not(HasSubstr("So I wait what"))) << out;
}

// A rule whose place fits look-alikes is asked which, once, by name;
// "the bin on the left pls" is the left bin. Before: "legos go in the left
// bin or the right bin", kept as it was, and the lego brick asked about.
TEST_F(FreshUsers, ARulesLookAlikePlaceIsAskedWhich) {
  const std::string out = teach("kidsroom.yaml", {"tidy the kids room", "clear the rug",
                                                  "stuffed animals go on the bed and legos in the bin", "the left one"});
  EXPECT_THAT(out, HasSubstr("Instructor: stuffed animals go on the bed and legos in the bin\n"
                             "Agent: Which bin do legos go in: the left bin or the right bin?\n"
                             "Instructor: the left one\n"
                             "Agent: So stuffed animals go on the bed and legos go in the left bin.\n"
                             "Agent: The lego brick on the rug goes in the left bin, with legos, as you said.\n"))
      << out;
  const std::string said = teach("kidsroom.yaml", {"tidy the kids room", "clear the rug",
                                                   "legos in the bin on the left pls"},
                                 "another.sqlite");
  EXPECT_THAT(said, HasSubstr("Instructor: legos in the bin on the left pls\n"
                              "Agent: So the lego brick goes in the left bin.\n"))
      << said;
}

// "X too" after a remark and a sentence ("thats just junk mail, recycle
// it. newspaper too"); a rule said after a yes with "there" for the place
// proposed ("yep. hats and caps go there too"); a where-question with a
// word nothing is called ("where'd you put the dogs ball"). Before: the
// newspaper and the hats were dropped without a word, and the ball was
// "I don't see a dogs ball; do you mean the tennis ball?", then "yeah the
// tennis ball" was not understood.
TEST_F(FreshUsers, ThingsSaidTooAndThereAndWhereWithAWordUnknown) {
  const std::string first = teach("mudroom.yaml", {"tidy the mudroom", "clear the bench",
                                                   "coats and jackets go on the top hooks, scarf in the left "
                                                   "basket, gloves in the right one",
                                                   "top hooks", "shelf", "top hook", "now the console table",
                                                   "keys in the bowl", "thats just junk mail, recycle it. newspaper too",
                                                   "closet", "that's all"});
  EXPECT_THAT(first, HasSubstr("Instructor: thats just junk mail, recycle it. newspaper too\n"
                               "Agent: I took \"thats just junk mail\" as a remark.\n"
                               "Agent: So the envelope goes in the recycling bin.\n"
                               "Agent: The same goes for the newspaper, when I come to it.\n"))
      << first;
  const std::string out =
      teach("mudroom2.yaml", {"tidy the mudroom", "yep. hats and caps go there too", "where'd you put the dogs ball",
                              "that's all"});
  EXPECT_THAT(out, HasSubstr("Instructor: yep. hats and caps go there too\n"
                             "Agent: So hats and caps go in the right basket.\n"
                             "Agent: So the mitten goes in the right basket.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: The beanie on the bench goes in the right basket, with hats, as you said.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: where'd you put the dogs ball\nAgent: The tennis ball is on the floor.\n"))
      << out;
}

// The second pair (a home office, a garden shed). What a person says
// before a thing ("hmm the mug") is no class, and "should be on" corrects
// at the next-step question. Before: "So hmm the mug goes on the desk.",
// kept as a rule, and the mug left in the cupboard.
TEST_F(FreshUsers, FillersBeforeAThingMakeNoRuleAndShouldBeCorrects) {
  const std::string out = teach("office.yaml", {"ugh my office is a disaster, can you help me tidy it up",
                                                "start with the desk i guess", "papers go in the filing cabinet",
                                                "mug goes in the cupboard", "top drawer", "same", "gross. trash",
                                                "bottom drawer", "hmm the mug should be on the desk actually, i use it all day",
                                                "that's all"});
  EXPECT_THAT(out, HasSubstr("Instructor: hmm the mug should be on the desk actually, i use it all day\n"
                             "Agent: So the mug goes on the desk.\n"
                             "Agent: I opened the cupboard, took the mug out of it, put it on the desk, and closed the "
                             "cupboard.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("hmm the mug goes"))) << out;
}

// Where a thing already dealt with goes, said at the question about
// another thing, is a correction; the question comes again. Before: "That
// says what becomes of the kneeling pad, but I asked about ...".
TEST_F(FreshUsers, ACorrectionAtAnotherThingsQuestionIsMade) {
  const std::string out = teach("shed.yaml", {"ugh the shed is a disaster after the weekend, lets tidy it up",
                                              "start with the stuff on the bench", "trowel goes in the cabinet, shears too",
                                              "seeds on the upper shelf", "hang the gloves on the left hook", "cabinet",
                                              "now the floor", "fair enough. actually the gloves should hang on the right hook"});
  EXPECT_THAT(out, HasSubstr("Instructor: fair enough. actually the gloves should hang on the right hook\n"
                             "Agent: So the gardening glove goes on the right hook.\n"
                             "Agent: I put two gardening gloves on the right hook.\n"
                             "Agent: Where should the garden hose on the floor go?\n"))
      << out;
}

// "ya. and the highlighter goes w the pens", said about the folder: the
// highlighter's words are not the folder's goal. Before: "So the folder
// goes in the top drawer", where the pens went.
TEST_F(FreshUsers, AnotherThingsGoalIsNotTheOneAskedAbout) {
  teach("office.yaml", {"tidy the home office", "clear the desk", "papers go in the filing cabinet", "cupboard",
                        "top drawer", "same", "trash", "bottom drawer", "that's all"});
  const std::string out = teach("office2.yaml", {"tidy the office", "yep, for taxes", "ya. and the highlighter goes w the pens"});
  EXPECT_THAT(out, HasSubstr("Agent: I know how to tidy the home office")) << out;
  // ("w" is read as "with" since stop 38: the reply is the highlighter's,
  // said back as such, where it was "I didn't catch where the folder should
  // go".)
  EXPECT_THAT(out, HasSubstr("Instructor: ya. and the highlighter goes w the pens\nAgent: That says what becomes of the "
                             "highlighter, but I asked about the folder on the desk."))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("So the folder goes in the top drawer"))) << out;
}

// The home office's teacher forgot a goal, then said where the thing goes
// and, later, "undo" to take the forget back. Before: the goal said after
// the forget was refused ("I asked for the next step of the task"), and
// "undo" undid the answer before the forget instead.
TEST_F(FreshUsers, AGoalForgottenIsSaidAgainOrTakenBackByUndo) {
  const std::vector<std::string> start = {"tidy the office", "start with the desk", "papers go in the filing cabinet",
                                          "cupboard", "top drawer", "same", "trash", "bottom drawer",
                                          "forget the stapler"};
  std::vector<std::string> replies = start;
  replies.insert(replies.end(), {"the stapler goes in the bottom drawer", "that's all"});
  std::string out = teach("office.yaml", replies);
  EXPECT_THAT(out, HasSubstr("Instructor: the stapler goes in the bottom drawer\n"
                             "Agent: So the stapler goes in the bottom drawer, and the bottom drawer ends closed.\n"
                             "Agent: I opened the top drawer, took the stapler out of it"))
      << out;
  replies = start;
  replies.insert(replies.end(), {"undo", "status", "that's all"});
  out = teach("office.yaml", replies, "second.sqlite");
  EXPECT_THAT(out, HasSubstr("Instructor: undo\nAgent: I know again where the stapler goes.\n")) << out;
  EXPECT_THAT(out, Not(HasSubstr("I forgot what you told me last"))) << out;
  EXPECT_THAT(out, HasSubstr("In the bottom drawer: the headset.")) << out;
}

// An undo after an undo goes straight back: the headset taken out of the
// bottom drawer by the first is not put back in only to be taken out
// again by the second, and what was opened is closed again.
TEST_F(FreshUsers, ASecondUndoGoesStraightBack) {
  const std::string out = teach("office.yaml", {"tidy the office", "start with the desk", "papers go in the filing cabinet",
                                                "cupboard", "top drawer", "same", "trash", "bottom drawer", "undo",
                                                "undo", "that's all"});
  EXPECT_THAT(out, HasSubstr("Agent: To put things back as they were, I opened the bottom drawer, took the headset "
                             "out of it, put it on the desk, and closed the bottom drawer.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: I forgot what you told me last: \"trash\".\n"
                             "Agent: To put things back as they were, I took the banana peel out of the wastebasket "
                             "and put it on the desk.\n"))
      << out;
}

// "no the charger goes in the top drawer. and the pen too, pens arent
// books", after the pen went on the bookshelf (the dorm room's teacher):
// a thing put away, said "too" at another thing's question, is moved
// where it now goes. Before: the pen's part was dropped without a word.
TEST_F(FreshUsers, AThingPutAwaySaidTooIsMoved) {
  const std::string out = teach("office.yaml", {"tidy the office", "start with the desk", "papers go in the filing cabinet",
                                                "cupboard", "top drawer", "bottom drawer", "trash",
                                                "bottom drawer, and the stapler too, it is heavy", "that's all"});
  EXPECT_THAT(out, HasSubstr("Agent: So the stapler goes in the bottom drawer, and the bottom drawer ends closed.\n"
                             "Agent: I opened the top drawer, took the stapler out of it, put it on the desk, closed "
                             "the top drawer, opened the bottom drawer, put the stapler in it, and closed it.\n"))
      << out;
}

// The craft room's teacher (stop 38, docs/fresh-users/craft-room.tsv), as
// typed up to the question before the replies that went wrong.
std::vector<std::string> craft_room_start() {
  return {"ok so my craft room is a disaster, can u tidy it up", "um start with the work table, everything on it",
          "clear it off", "all the paints go in the cabinet", "brushes always go in the jar",
          "yarn goes in the plastic tub, and knitting needles too", "top drawr", "yes drawer. the top one", "top!",
          "same place as the scissors. markers too", "whats left?",
          "sketchbook in the bottom drawer pls and the tape too", "trash obviously", "in the trash",
          "why did u put the knitting needle in the tub",
          "oh actually the glue stick goes in the bottom drawer, not the top one", "hmm no undo that",
          "ok now the shelf", "just leave the mug, ill take it to the kitchen later",
          "crochet hook goes with the knitting stuff", "same as the knitting needle", "um pencils go w/ the markers",
          "pencils go with the markers", "wheres the glue?", "yeah the glue stick, where is it",
          "where's the glue stick?", "open the cabinet for a sec", "ok close it again", "status",
          "why did you put the markers in the top drawer?"};
}

// At the next-step question: a correction after "no wait" (it was the part
// "clear the shelf"); a rule for a kind not in the room (asked back three
// times: "What should I do with the things in the tub?", then kept as the
// class "fyi ribbons"); and "ok cool thats all, we're done" (the part "cool
// what is in the tub", kept in the task).
TEST_F(FreshUsers, TheCraftRoomsNextStepReplies) {
  std::vector<std::string> replies = craft_room_start();
  replies.insert(replies.end(), {"no wait, the sketchbook should be on the shelf, its too big for the drawer",
                                 "oh and fyi ribbons go in the tub too", "ok cool thats all, we're done"});
  const std::string out = teach("craft.yaml", replies);
  EXPECT_THAT(out, HasSubstr("its too big for the drawer\nAgent: So the sketchbook goes on the shelf.\n")) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: oh and fyi ribbons go in the tub too\n"
                             "Agent: So ribbons go in the plastic tub.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: ok cool thats all, we're done\nAgent: So the task is done.\n")) << out;
  EXPECT_THAT(out, Not(HasSubstr("cool what is"))) << out;
}

// The fourth pair (stop 39: a garage and a laundry room, their own worlds).
// "ya. paper stuff all goes in recycling" was read with "ya" as "you";
// "forget paper" then forgot the newspaper's goal, not the rule, and the
// question about the rule was asked again after it was forgotten.
TEST_F(FreshUsers, ARuleIsForgottenByItsWordsAndTheQuestionOnItGoes) {
  const std::string out = teach("garage.yaml", {"tidy the garage", "start with the floor",
                                                "all the paint goes on the top shelf",
                                                "ya. paper stuff all goes in recycling", "forget paper", "quit"});
  EXPECT_THAT(out, HasSubstr("Instructor: ya. paper stuff all goes in recycling\n"
                             "Agent: So paper stuff goes in the recycling bin.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("I did not follow \"you\""))) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: forget paper\n"
                             "Agent: I forgot that paper things go in the recycling bin, as said: \"ya. paper stuff "
                             "all goes in recycling\"; I will ask where such things go.\n"
                             "Agent: Where should the cardboard box on the floor go?\n"))
      << out;
}

// "hamper. close the lid after, the cat gets in there": the t-shirt goes in
// the hamper, closed, and the cat is a reason. It was kept as a rule that
// "lid after" and "cat" go in the left basket, which then took the jeans,
// the towel and the dryer sheet alone.
TEST_F(FreshUsers, AReasonAboutSomethingNotHereMakesNoRule) {
  const std::string out =
      teach("laundry.yaml", {"ok so the laundry room is a disaster, can you help me clean it up",
                             "um start with the floor, all that stuff needs picking up",
                             "socks go in the left basket, thats my whites pile",
                             "hamper. close the lid after, the cat gets in there", "quit"});
  EXPECT_THAT(out, HasSubstr("Instructor: hamper. close the lid after, the cat gets in there\n"
                             "Agent: I took \"the cat gets in there\" as a reason, not an instruction.\n"
                             "Agent: So the dirty red t shirt goes in the hamper, and the hamper ends closed.\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("So lid after"))) << out;
  EXPECT_THAT(out, Not(HasSubstr("with lid after"))) << out;
}

// "leave the washer open from now on" (a fresh user's laundry room) was
// read as a part of the task over the washer; "i want it left open" was
// dropped. A door the teacher wants left open is opened now, the goals
// that closed it leave it open, the norm no longer closes it, "why is the
// washer open?" says so, and "undo" takes it all back.
TEST_F(FreshUsers, ADoorLeftOpenFromNowOnStaysOpen) {
  const std::string out =
      teach("laundry.yaml", {"tidy the laundry room", "clear the floor", "socks go in the left basket",
                             "the t shirt goes in the hamper", "the jeans go in the washer",
                             "leave the washer open from now on", "the towel goes in the washer",
                             "why is the washer open?", "undo", "undo", "the towel goes in the washer", "quit"});
  EXPECT_THAT(out, HasSubstr("Instructor: leave the washer open from now on\n"
                             "Agent: I will leave the washer open from now on, also after putting the jeans in it.\n"
                             "Agent: I opened the washer.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: the towel goes in the washer\n"
                             "Agent: So the dirty towel goes in the washer.\n"
                             "Agent: I put the dirty towel in the washer.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: why is the washer open?\n"
                             "Agent: The washer is open: you told me to leave it open from now on.\n"))
      << out;
  // Two undos: the towel, then the door; the towel goes in and the washer
  // is closed again, by the norm.
  EXPECT_THAT(out, HasSubstr("Instructor: the towel goes in the washer\n"
                             "Agent: So the dirty towel goes in the washer, and the washer ends closed.\n"))
      << out;
}

// "ok the folding table next. detergent and stain remover go in the
// cabinet" started the part and dropped the goals. Where things go, said
// after a part, answers the part's first question.
TEST_F(FreshUsers, WhereThingsGoSaidWithAPartAnswersItsFirstQuestion) {
  const std::string out =
      teach("laundry.yaml", {"tidy the laundry room", "clear the floor", "i'm done", "yes",
                             "ok the folding table next. detergent and stain remover go in the cabinet", "quit"});
  EXPECT_THAT(out, HasSubstr("Instructor: ok the folding table next. detergent and stain remover go in the cabinet\n"
                             "Agent: So I clear what is on the folding table, one thing at a time.\n"
                             "Agent: So the detergent goes in the cabinet, and the cabinet ends closed."))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: The same goes for the stain remover, when I come to it.\n")) << out;
  EXPECT_THAT(out, Not(HasSubstr("Where should the detergent"))) << out;
}

}  // namespace
}  // namespace apprentice
