// Two norms of a patient helper at the terminal (`apprentice teach`, the
// real binary):
//  - a person's class rule goes alone only to the things WordNet or their
//    names put in its class; a thing the word vectors only relate to it is
//    asked about, with the class named, and a "no" is kept;
//  - a door opened to put something away is closed after, unless the
//    teacher says to leave it open, and the read-back says so;
//  - "open the drawer" where two drawers look alike is asked which, never
//    done to both.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/scratch.h"
#include "process.h"

namespace apprentice {
namespace {

using testing::Process;
using ::testing::HasSubstr;
using ::testing::Not;

// An art room: the paintbrush is a brush to WordNet; the paint pot and the
// sponge are not, though "paint" and "sponge" lie near "brushes" in the
// vectors.
constexpr const char* kArtRoom = R"(name: art-room
domain: kitchen
location: classroom
places:
  - {category: table, kind: surface}
  - {category: sink, kind: receptacle}
  - {category: cupboard, kind: receptacle, door: closed}
objects:
  - {category: paintbrush, at: table1}
  - {category: paint-pot, at: table1}
  - {category: sponge, at: table1}
)";

class TeachNorms : public testing::ScratchTest {};

// Found by hand in a classroom: "the brushes go in the sink", said at the
// paint pot's question, put the paint pot in the sink "as you said".
TEST_F(TeachNorms, AClassRuleIsAskedNotActedOnForAThingItDoesNotName) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("art-room.yaml", kArtRoom).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the classroom", "clear the table", "the sink", "the brushes go in the sink",
                                 "no, it goes in the cupboard", "yes", "that is all"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: the brushes go in the sink\n"
                             "Agent: So brushes go in the sink.\n"
                             "Agent: Does the paint pot on the table go with brushes, as you said: it goes in the "
                             "sink?\n"))
      << out;
  EXPECT_THAT(out, Not(HasSubstr("The paint pot on the table goes in the sink"))) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: no, it goes in the cupboard\n"
                             "Agent: So the paint pot goes in the cupboard, and the cupboard ends closed."))
      << out;
  EXPECT_THAT(out, HasSubstr("Agent: Does the sponge on the table go with brushes, as you said: it goes in the "
                             "sink?\nInstructor: yes\nAgent: So the sponge goes in the sink.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("The task is learned")) << out;
}

// The rule said first, at the paintbrush's question: the paintbrush, a
// brush to WordNet, goes to the sink without a question; the sponge, in
// neither class, is asked about.
TEST_F(TeachNorms, AClassRuleGoesAloneToWhatWordNetPutsInIt) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("art-room.yaml", kArtRoom).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the classroom", "clear the table", "brushes go in the sink, pots in the cupboard",
                                 "quit"})));
  teach.wait();
  const std::string& out = teach.out();
  const std::size_t said = out.find("Instructor: brushes go in the sink");
  ASSERT_NE(said, std::string::npos) << out;
  const std::string after = out.substr(said);
  EXPECT_THAT(after, HasSubstr("So the paintbrush goes in the sink")) << out;
  EXPECT_THAT(after, Not(HasSubstr("the paintbrush on the table go"))) << out;
  EXPECT_THAT(after, HasSubstr("Agent: Where should the sponge on the table go?\n")) << out;
}

// "the dishwasher" for a thing, said by a person who did not think of the
// door: it is closed after, and why is said once. "leave it open" keeps
// another door open; goals said with the door ("and close it") are as said.
TEST_F(TeachNorms, ADoorOpenedToPutSomethingAwayIsClosedUnlessToldToLeaveItOpen) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/tidy-kitchen.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy kitchen", "clear the table", "the dishwasher", "the fridge and leave it open",
                                 "the pantry", "quit"})));
  teach.wait();
  const std::string& out = teach.out();
  const std::string note = "I close what I open; say \"leave it open\" when something should stay open.";
  EXPECT_THAT(out, HasSubstr("Instructor: the dishwasher\n"
                             "Agent: So the ceramic plate goes in the dishwasher, and the dishwasher ends closed. " +
                             note + "\nAgent: I opened the dishwasher, put the ceramic plate in it, and closed it.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("Instructor: the fridge and leave it open\n"
                             "Agent: So the metal fork goes in the fridge, and the fridge ends open.\n"
                             "Agent: I opened the fridge and put the metal fork in it.\n"))
      << out;
  // Said once a session.
  EXPECT_EQ(out.find(note), out.rfind(note)) << out;
  EXPECT_THAT(out, HasSubstr("Instructor: the pantry\n"
                             "Agent: So the glass tumbler goes in the pantry, and the pantry ends closed.\n"))
      << out;
}

// "same as X but leave the door open": what is said after "but" wins over
// what X's goal says of the door (found by a newcomer: "..., the top drawer
// ends open, and the top drawer ends closed", a goal no plan can reach).
TEST_F(TeachNorms, SameAsAnotherButLeaveTheDoorOpenLeavesItOpen) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/tidy-kitchen.yaml").string()});
  ASSERT_TRUE(teach.write(
      testing::typed_lines({"tidy kitchen", "clear the table", "the dishwasher", "same as the plate but leave the door open", "quit"})));
  teach.wait();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: same as the plate but leave the door open\n"
                                     "Agent: So the metal fork goes in the dishwasher, and the dishwasher ends open.\n"
                                     "Agent: I opened the dishwasher and put the metal fork in it.\n"))
      << teach.out();
}

// "start with the stuff on the floor" is a step said without its verb, the
// surface's part (cleared, and said so), not a rule about "start with the
// stuff" (found by a newcomer: "So start with the stuff go on the
// floor.").
TEST_F(TeachNorms, AStepWithoutItsVerbIsItsPlacesPartNotARule) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/tidy-kitchen.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy kitchen", "start with the stuff on the table", "quit"})));
  teach.wait();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: start with the stuff on the table\n"
                                     "Agent: I took \"start with the stuff on the table\" as clearing the table.\n"))
      << teach.out();
  EXPECT_THAT(teach.out(), Not(HasSubstr("So start with"))) << teach.out();
  EXPECT_THAT(teach.out(), HasSubstr("Agent: So I clear what is on the table, one thing at a time.\n")) << teach.out();
}

// Found by a newcomer in an office of their own: "open the drawer" opened
// the top and the bottom drawer.
TEST_F(TeachNorms, OpeningOneOfTwoLookAlikesAsksWhichAndOpensThatOne) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", testing::source_path("data/scenarios/tidy-garage.yaml").string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the garage", "clear the workbench", "open the drawer", "the top one", "quit"})));
  teach.wait();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: open the drawer\n"
                                     "Agent: Which drawer: the top drawer or the bottom drawer?\n"
                                     "Instructor: the top one\n"
                                     "Agent: I opened the top drawer.\n"
                                     "Agent: Where should the hammer on the workbench go?\n"))
      << teach.out();
  EXPECT_THAT(teach.out(), Not(HasSubstr("opened the bottom drawer"))) << teach.out();
}

// Said at a proposed goal in place of yes or no (found by a newcomer):
// where the thing goes, after a marker, is a "no" with that goal; an
// ending asks back about the rest of the part and leaves it, as at a
// where-question. Neither is "Please answer yes or no."
TEST_F(TeachNorms, AGoalOrAnEndingSaidAtAProposalIsTakenNotRefused) {
  const std::string world = write("art-room.yaml", kArtRoom).string();
  Process instead({APPRENTICE_BINARY, "teach", "--scenario", world});
  ASSERT_TRUE(instead.write(testing::typed_lines({"tidy the classroom", "clear the table", "the sink", "the brushes go in the sink",
                                   "hang on, the paint pot goes in the cupboard", "yes", "that is all"})));
  EXPECT_EQ(instead.wait(), 0) << instead.out() << instead.err();
  EXPECT_THAT(instead.out(), HasSubstr("Instructor: hang on, the paint pot goes in the cupboard\n"
                                       "Agent: So the paint pot goes in the cupboard"))
      << instead.out();
  EXPECT_THAT(instead.out(), Not(HasSubstr("Please answer yes or no."))) << instead.out();

  Process ending({APPRENTICE_BINARY, "teach", "--scenario", world});
  ASSERT_TRUE(ending.write(testing::typed_lines({"tidy the classroom", "clear the table", "the sink", "the brushes go in the sink",
                                  "ok I'm done", "yes", "that is all"})));
  EXPECT_EQ(ending.wait(), 0) << ending.out() << ending.err();
  const std::string& out = ending.out();
  EXPECT_THAT(out, HasSubstr("Instructor: ok I'm done\n"
                             "Agent: There are still 2 things on the table: the paint pot and the sponge. Shall I "
                             "leave them?\n"
                             "Instructor: yes\n"
                             "Agent: So I leave the paint pot and the sponge on the table, and this part of the task "
                             "is done.\n"
                             "Agent: What should I do next to tidy the classroom?\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("The task is learned")) << out;
}

// Found in set 7: "yes but leave the door open", said to a proposed goal,
// was taken as a bare yes and the door closed. A yes with more said of the
// place is the place proposed with that.
TEST_F(TeachNorms, AYesThatSaysMoreOfTheDoorKeepsIt) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("art-room.yaml", kArtRoom).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the classroom", "clear the table", "the cupboard",
                                 "the brushes go in the cupboard", "yes but leave the door open", "the sink",
                                 "that is all"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  EXPECT_THAT(teach.out(), HasSubstr("Instructor: yes but leave the door open\n"
                                     "Agent: So the paint pot goes in the cupboard, and the cupboard ends open.\n"
                                     "Agent: I opened the cupboard and put the paint pot in it.\n"))
      << teach.out();
}

// Where a goal decided by a person's class rule came from is kept in
// English, as `knowledge` shows it: never the log's "clothes -> in the
// laundry-hamper (person; 0.95)".
TEST_F(TeachNorms, AGoalFromAPersonsClassRuleSaysWhereItCameFromInEnglish) {
  constexpr const char* kBedroom = R"(name: bedroom
domain: kitchen
location: bedroom
places:
  - {category: bed, kind: surface}
  - {category: laundry-hamper, kind: receptacle}
objects:
  - {category: sock, at: bed1}
  - {category: t-shirt, at: bed1}
)";
  const std::string store = (dir_ / "bedroom.sqlite").string();
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("bedroom.yaml", kBedroom).string(), "--knowledge",
                 store});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the bedroom", "clear the bed", "clothes go in the hamper", "that is all"})));
  ASSERT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  Process knowledge({APPRENTICE_BINARY, "knowledge", "--knowledge", store});
  ASSERT_EQ(knowledge.wait(), 0) << knowledge.err();
  EXPECT_THAT(knowledge.out(), HasSubstr("clothes go in the laundry hamper, as said: \"clothes go in the hamper\""))
      << knowledge.out();
  EXPECT_THAT(knowledge.out(), Not(HasSubstr("->"))) << knowledge.out();
}

// A one-off action said before the next part ("open the cupboard, then
// clear the table") is done, and the part after it taken as the answer:
// the question is not asked again.
TEST_F(TeachNorms, AOneOffActionBeforeAPartIsDoneAndThePartTaken) {
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("art-room.yaml", kArtRoom).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the classroom", "ok now open the cupboard, then clear the table", "the sink",
                                 "the cupboard", "the sink", "that is all"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: ok now open the cupboard, then clear the table\n")) << out;
  EXPECT_THAT(out, HasSubstr("I opened the cupboard.")) << out;
  EXPECT_THAT(out, HasSubstr("Agent: So I clear what is on the table, one thing at a time.\n")) << out;
  EXPECT_EQ(out.find("What should I do first to tidy the classroom?", out.find("then clear the table")),
            std::string::npos)
      << out;
}

// Found in a greenhouse: "pots go on the right shelf", said when asked for
// the first part of the task, was refused ("There is nothing on the right
// shelf now"), where "tools go in the top bin" was kept. Said of the
// world's own kind, with no part of the task in it, it is where every pot
// goes. And "pots" are pots, not every container: the seed packet (a
// packet, a container) is asked about, not put with them.
TEST_F(TeachNorms, WhereAKindGoesSaidForAPartOfTheTaskIsKeptForEveryThingOfIt) {
  constexpr const char* kPottingRoom = R"(name: potting-room
domain: kitchen
location: greenhouse
places:
  - {category: table, kind: surface}
  - {category: shelf, kind: surface, properties: [left]}
  - {category: shelf, kind: surface, properties: [right]}
  - {category: bin, kind: receptacle}
objects:
  - {category: pot, at: table1, count: 2}
  - {category: seed-packet, at: table1}
)";
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("potting-room.yaml", kPottingRoom).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the greenhouse", "pots go on the right shelf", "clear the table", "no",
                                 "in the bin", "that is all"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: pots go on the right shelf\nAgent: So pots go on the right shelf.\n")) << out;
  EXPECT_THAT(out, HasSubstr("The pot on the table goes on the right shelf, with pots, as you said.")) << out;
  EXPECT_THAT(out, Not(HasSubstr("I put the seed packet on the right shelf"))) << out;
  EXPECT_THAT(out, HasSubstr("I put the seed packet in the bin.")) << out;
}

// Found in a greenhouse: "now the floor, and the bucket after that", said
// after the potting bench was cleared, got "What should I do with the
// things on the floor?": the reader knew to take the last part's verb, but
// the agent never told it the parts taught.
TEST_F(TeachNorms, APlaceNamedForTheNextPartTakesTheLastPartsVerb) {
  constexpr const char* kTwoSurfaces = R"(name: two-surfaces
domain: kitchen
location: classroom
places:
  - {category: table, kind: surface}
  - {category: floor, kind: surface}
  - {category: sink, kind: receptacle}
  - {category: cupboard, kind: receptacle}
  - {category: bucket, kind: receptacle}
objects:
  - {category: paintbrush, at: table1}
  - {category: sponge, at: floor1}
  - {category: rag, at: bucket1}
)";
  Process teach({APPRENTICE_BINARY, "teach", "--scenario", write("two-surfaces.yaml", kTwoSurfaces).string()});
  ASSERT_TRUE(teach.write(testing::typed_lines({"tidy the classroom", "clear the table", "the sink",
                                 "now the floor, and the bucket after that", "the cupboard", "the sink",
                                 "that is all"})));
  EXPECT_EQ(teach.wait(), 0) << teach.out() << teach.err();
  const std::string& out = teach.out();
  EXPECT_THAT(out, HasSubstr("Instructor: now the floor, and the bucket after that\n"
                             "Agent: So I clear what is on the floor, one thing at a time.\n"))
      << out;
  EXPECT_THAT(out, HasSubstr("I put the sponge in the cupboard.")) << out;
  EXPECT_THAT(out, HasSubstr("So I empty what is in the bucket, one thing at a time.")) << out;
  EXPECT_THAT(out, HasSubstr("I took the rag out of the bucket and put it in the sink.")) << out;
}

}  // namespace
}  // namespace apprentice
