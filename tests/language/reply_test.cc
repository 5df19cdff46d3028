// read_reply beyond the kitchen's corpus: look-alikes told apart by
// properties, a kind of place that names every place of it, names with
// function words, phrasal verbs, the reasons and examples of unusable
// replies, and that the reader is total, in an office world of its own.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "language/generation.h"
#include "language/narration.h"
#include "language/reply.h"
#include "language_fixtures.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::kitchen30;
using testing::source_path;

constexpr std::string_view kOffice = R"(
name: test-office
domain: ../domains/kitchen.pddl
location: office
places:
  - {category: desk, kind: surface}
  - {category: counter, kind: surface}
  - {category: drawer, kind: receptacle, door: closed, properties: [top]}
  - {category: drawer, kind: receptacle, door: closed, properties: [bottom]}
  - {category: bookshelf, kind: receptacle}
  - {category: walk-in-pantry, kind: receptacle, door: closed}
  - {category: bag, kind: receptacle, properties: [blue]}
  - {category: bag, kind: receptacle, properties: [red]}
  - {category: bag, kind: receptacle, properties: [green]}
  - {category: garbage, kind: receptacle}
  - {category: toy-box, kind: receptacle}
objects:
  - {category: stapler, at: desk1}
  - {category: book, at: desk1}
  - {category: apple-core, at: desk1}
  - {category: mug, at: desk1}
  - {category: mug, at: counter1}
  - {category: half-and-half, at: bag1}
  - {category: jack-in-the-box, at: bag2}
  - {category: crackers, at: bag3}
task:
  name: organize office
  subtasks:
    - {verb: clear, place: desk1}
intent:
  - {subtask: clear, category: stapler, receptacle: drawer1, closed: true}
  - {subtask: clear, category: book, receptacle: bookshelf1}
  - {subtask: clear, category: apple-core, receptacle: garbage1}
  - {subtask: clear, category: mug, receptacle: drawer2, closed: true}
)";

// The office, with the properties people tell its look-alikes by.
const World& office() {
  static const World world = [] {
    auto loaded = parse_scenario(kOffice, source_path("data/scenarios/test-office.yaml"));
    if (!loaded) {
      ADD_FAILURE() << loaded.error().describe();
      std::abort();
    }
    return loaded->world;
  }();
  return world;
}

ObjectId in(const World& world, std::string_view name) {
  auto id = world.universe->find(name);
  EXPECT_TRUE(id.has_value()) << name;
  return id.value_or(0);
}

ReplyContext asking(Asked asked, std::optional<ObjectId> object = std::nullopt) {
  ReplyContext context;
  context.asked = asked;
  context.object = object;
  return context;
}

std::string read(const World& world, const ReplyContext& context, std::string_view text) {
  return format_reply(world, read_reply(grounder(), world, context, text));
}

std::string office_goal(std::string_view object, std::string_view text) {
  return read(office(), asking(Asked::kGoal, in(office(), object)), text);
}

// --- Properties as adjectives (issue 10, item 2) --------------------------------

TEST(ReplyProperties, TellLookAlikesApart) {
  EXPECT_EQ(office_goal("stapler1", "put it in the top drawer"), "goal (in stapler1 drawer1)");
  EXPECT_EQ(office_goal("stapler1", "the bottom drawer, and close it"),
            "goal (and (in stapler1 drawer2) (closed drawer2))");
  EXPECT_EQ(office_goal("stapler1", "the stapler goes in the top drawer with the door shut"),
            "goal (and (in stapler1 drawer1) (closed drawer1))");
  // The grammar's sentences take them too.
  Interpretation grammar = grounder().interpret(
      "the goal is that the stapler is in the top drawer and the top drawer is closed", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), grammar.result), "goal (and (in stapler1 drawer1) (closed drawer1))");
}

TEST(ReplyProperties, StillAmbiguousAsksWhich) {
  Reply reply = read_reply(grounder(), office(), asking(Asked::kGoal, in(office(), "stapler1")), "in the drawer");
  const auto* ambiguous = std::get_if<Ambiguous>(&reply);
  ASSERT_NE(ambiguous, nullptr) << format_reply(office(), reply);
  EXPECT_EQ(ambiguous->question, "Which drawer: the top drawer or the bottom drawer?");
  EXPECT_EQ(ambiguous->candidates, (std::vector<ObjectId>{in(office(), "drawer1"), in(office(), "drawer2")}));
  // The answer to that question.
  ReplyContext which = asking(Asked::kWhich);
  which.choices = ambiguous->candidates;
  EXPECT_EQ(read(office(), which, "the top one"), "chosen drawer1");
  EXPECT_EQ(read(office(), which, "bottom"), "chosen drawer2");
  EXPECT_EQ(read(office(), which, "the bottom drawer please"), "chosen drawer2");
  EXPECT_EQ(read(office(), which, "drawer1"), "chosen drawer1");
  // A property nothing here has is not a guess.
  EXPECT_EQ(read(office(), which, "the left one"), "unusable");
  // The reply read again with the answer.
  ReplyContext again = asking(Asked::kGoal, in(office(), "stapler1"));
  again.settled = {{ambiguous->phrase, in(office(), "drawer2")}};
  EXPECT_EQ(read(office(), again, "in the drawer"), "goal (in stapler1 drawer2)");
  EXPECT_EQ(read(office(), again, "the goal is that the stapler is in the drawer"), "goal (in stapler1 drawer2)");
  // "left" is no drawer's property: the question again, not either drawer.
  EXPECT_EQ(office_goal("stapler1", "put it in the left drawer"), "ambiguous left drawer: drawer1 drawer2");
}

TEST(ReplyProperties, ExamplesAndQuestionsUseThem) {
  EXPECT_EQ(distinct_noun_for(office(), in(office(), "drawer2")), "the bottom drawer");
  EXPECT_EQ(distinct_noun_for(office(), in(office(), "bookshelf1")), "the bookshelf");
  ReplyContext which = asking(Asked::kWhich);
  which.choices = {in(office(), "bag1"), in(office(), "bag3")};
  EXPECT_EQ(example_replies(office(), which), (std::vector<std::string>{"the blue bag", "the green bag"}));
}

// --- A kind of place names every place of it (item 3) ------------------------------

TEST(ReplyCategoryPlaces, EveryBag) {
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(office(), step, "Repeat the following tasks while an object is in a bag."), "loop in bag1 bag2 bag3");
  EXPECT_EQ(read(office(), step, "Unload an object that is in a bag."), "subtask unload in bag1 bag2 bag3");
  EXPECT_EQ(read(office(), step, "unload the bags"), "subtask unload in bag1 bag2 bag3");
  EXPECT_EQ(read(office(), step, "unload the bag"), "subtask unload in bag1 bag2 bag3");
  EXPECT_EQ(read(office(), step, "empty everything out of the bags"), "subtask empty in bag1 bag2 bag3");
  EXPECT_EQ(read(office(), step, "empty the blue bag"), "subtask empty in bag1");
  // The grounder says so too.
  Interpretation grammar =
      grounder().interpret("Unload an object that is in a bag.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), grammar.result), "subtask unload in bag1");
  const auto& step_grounded = std::get<TaskStep>(grammar.result);
  EXPECT_EQ(step_grounded.places.size(), 3u);
}

// --- Replies of a person who describes before asking ---------------------------

// "garage" is also a verb in WordNet (to garage a car); a piece that goes on
// with "is" describes and names no task.
TEST(ReplyTask, ADescriptionIsNotTheTasksName) {
  static const Scenario garage = apprentice::testing::shipped_scenario("tidy-garage");
  ReplyContext task = asking(Asked::kTask);
  EXPECT_EQ(read(garage.world, task, "the garage is a mess, let's tidy it up"), "task tidy garage");
  EXPECT_EQ(read(garage.world, task, "The garage is a mess. Tidy it."), "task tidy garage");
  EXPECT_EQ(read(garage.world, task, "let's tidy the garage"), "task tidy garage");
  Reply only = read_reply(grounder(), garage.world, task, "the garage is a mess");
  EXPECT_TRUE(std::holds_alternative<Unusable>(only)) << format_reply(garage.world, only);
  // A subject first is a description too ("kid" is a verb in WordNet); the
  // frame "the task is to" is not.
  static const Scenario playroom = apprentice::testing::shipped_scenario("playroom");
  EXPECT_EQ(read(playroom.world, task, "the kids left a mess in here. can you tidy up the playroom?"), "task tidy playroom");
  EXPECT_EQ(read(playroom.world, task, "the task is to tidy the playroom"), "task tidy playroom");
  // Picking everything up off a place clears it (known_verbs.h).
  EXPECT_EQ(read(playroom.world, asking(Asked::kTaskStep), "first pick up everything off the floor"),
            "subtask clear on floor1");
  // "the blue one": a property alone names the look-alike that has it.
  ReplyContext car = asking(Asked::kGoal, in(playroom.world, "toy-car1"));
  EXPECT_EQ(read(playroom.world, car, "the cars go into the blue one"), "goal (in toy-car1 bin2)");
  EXPECT_EQ(read(playroom.world, car, "put it in the green one"), "goal (in toy-car1 bin3)");
}

// "the drawer" right after a placement in one drawer is that drawer; without
// a placement it is still asked about.
TEST(ReplyReferences, ThePlaceJustNamedSettlesALookAlikeInTheSameReplyOrInAClosing) {
  ReplyContext goal = asking(Asked::kGoal, in(office(), "stapler1"));
  EXPECT_EQ(read(office(), goal, "put it in the top drawer and shut the drawer"),
            "goal (and (in stapler1 drawer1) (closed drawer1))");
  Reply unsettled = read_reply(grounder(), office(), goal, "put it in the drawer and shut it");
  EXPECT_TRUE(std::holds_alternative<Ambiguous>(unsettled)) << format_reply(office(), unsettled);
  // After a placement in the bottom drawer, a new destination said by kind
  // alone is still asked which (the teacher may mean the other); a closing
  // of "the drawer" is the one named last.
  goal.recent_place = in(office(), "drawer2");
  Reply again = read_reply(grounder(), office(), goal, "put it in the drawer and shut it");
  EXPECT_TRUE(std::holds_alternative<Ambiguous>(again)) << format_reply(office(), again);
  ReplyContext action = asking(Asked::kAction, in(office(), "stapler1"));
  action.recent_place = in(office(), "drawer2");
  EXPECT_EQ(read(office(), action, "shut the drawer"), "action (close drawer2)");
}

// --- Names with function words (item 4) ---------------------------------------------

TEST(ReplyNames, FunctionWordsInsideNames) {
  EXPECT_EQ(office_goal("half-and-half1", "put it in the walk in pantry"), "goal (in half-and-half1 walk-in-pantry1)");
  EXPECT_EQ(office_goal("half-and-half1", "the half and half goes in the walk-in pantry and the walk-in pantry is closed"),
            "goal (and (in half-and-half1 walk-in-pantry1) (closed walk-in-pantry1))");
  EXPECT_EQ(office_goal("jack-in-the-box1", "the jack in the box goes in the toy box"),
            "goal (in jack-in-the-box1 toy-box1)");
  for (std::string_view sentence :
       {"the goal is that the half and half is in the walk in pantry and the walk in pantry is closed",
        "If the object is a half-and-half then the goal is that the object is in the walk-in pantry and the walk in "
        "pantry is closed."}) {
    Interpretation grammar = grounder().interpret(sentence, office(), in(office(), "half-and-half1"));
    EXPECT_EQ(format_grounding(office(), grammar.result),
              "goal (and (in half-and-half1 walk-in-pantry1) (closed walk-in-pantry1))")
        << sentence;
  }
  Interpretation open = grounder().interpret("Open the walk in pantry.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), open.result), "action (open walk-in-pantry1)");
  Interpretation put = grounder().interpret("Put the jack in the box in the toy box.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), put.result), "action (put-in jack-in-the-box1 toy-box1)");
}

// --- Phrasal verbs (item 4) -----------------------------------------------------------

TEST(ReplyPhrasalVerbs, AsSubtaskVerbsAndInSentences) {
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(office(), step, "Put away an object that is on the desk."), "subtask put away on desk1");
  EXPECT_EQ(read(office(), step, "put away the things on the desk"), "subtask put away on desk1");
  EXPECT_EQ(read(office(), step, "put the stuff on the desk away"), "subtask put away on desk1");
  Interpretation grammar = grounder().interpret("Put away an object that is on the desk.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), grammar.result), "subtask put away on desk1");
  EXPECT_EQ(office_goal("apple-core1", "throw away the apple core"), "goal (in apple-core1 garbage1)");
  EXPECT_EQ(office_goal("book1", "put the book away in the bookshelf"), "goal (in book1 bookshelf1)");
  EXPECT_EQ(office_goal("book1", "put the book back on the bookshelf"), "goal (in book1 bookshelf1)");
  Interpretation put_away = grounder().interpret("Put the book away in the bookshelf.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), put_away.result), "action (put-in book1 bookshelf1)");
  Interpretation pick = grounder().interpret("Pick the book up.", office(), std::nullopt);
  EXPECT_EQ(format_grounding(office(), pick.result), "action (pick-up book1 desk1)");
  // Without a place it is a question, not a guess.
  Reply away = read_reply(grounder(), office(), asking(Asked::kAction, in(office(), "book1")), "put the book away");
  ASSERT_TRUE(std::holds_alternative<Unusable>(away));
  EXPECT_NE(std::get<Unusable>(away).reason.find("Where"), std::string::npos);
}

// --- The structure, after a first subtask -------------------------------------------------

TEST(ReplyStructure, APlaceWithoutAVerbTakesTheLastSubtasksVerb) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  Reply bare = read_reply(grounder(), kitchen, step, "the counter next");
  ASSERT_TRUE(std::holds_alternative<Unusable>(bare)) << format_reply(kitchen, bare);
  EXPECT_EQ(std::get<Unusable>(bare).reason, "What should I do with the things on the counter?");
  // Its own example comes first, and the reason does not give one too
  // (the agent said "For example: ... You could say, for example, ...").
  ASSERT_FALSE(std::get<Unusable>(bare).examples.empty());
  EXPECT_EQ(std::get<Unusable>(bare).examples.front(), "clear the counter");
  EXPECT_LE(std::get<Unusable>(bare).examples.size(), 2u);
  step.taught_subtasks = {"clear"};
  EXPECT_EQ(read(kitchen, step, "the counter next"), "subtask clear on counter1");
  EXPECT_EQ(read(kitchen, step, "now do the same with the counter"), "subtask clear on counter1");
  EXPECT_EQ(read(kitchen, step, "then do the dish rack"), "subtask clear in dish-rack1");
  EXPECT_EQ(read(kitchen, step, "now unload the dish rack"), "subtask unload in dish-rack1");
  // (A part's ending is asked back here: APartsEndingAtTheTasksNextStepIsAskedBack.)
  EXPECT_EQ(read(kitchen, step, "that's all for the table"), "unusable");
  // The last verb is for places of another kind, or no general one: asked
  // back (sorting a table, clearing a rack, may not be what was meant).
  EXPECT_EQ(read(kitchen, step, "the dish rack next"), "unusable");
  step.taught_subtasks = {"sort"};
  EXPECT_EQ(read(kitchen, step, "the counter next"), "unusable");
  step.taught_subtasks = {"clear", "empty"};
  EXPECT_EQ(read(kitchen, step, "the dish rack next"), "subtask empty in dish-rack1");
}

// Found in set 7: "tip out the bucket" was a part named "tip". A verb with
// "out" before a receptacle takes what is in it out; at a surface, "out"
// adds nothing ("sort out the counter" sorts it).
TEST(ReplyStructure, AVerbWithOutAtAReceptacleEmptiesIt) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(kitchen, step, "tip out the dish rack"), "subtask empty in dish-rack1");
  EXPECT_EQ(read(kitchen, step, "tip the dish rack out"), "subtask empty in dish-rack1");
  EXPECT_EQ(read(kitchen, step, "sort out the counter"), read(kitchen, step, "sort the counter"));
}

// Found in set 8: "start with the table", "the sink first", as the first
// part, were asked back. Before any part is taught, a place named alone is
// its kind's part (clear a surface, empty a receptacle), said in the
// read-back; after a part of another verb it is still asked.
TEST(ReplyStructure, APlaceNamedAloneFirstIsItsKindsPart) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(kitchen, step, "start with the counter"), "subtask clear on counter1");
  // A receptacle's things may be emptied, unloaded or sorted: asked.
  EXPECT_EQ(read(kitchen, step, "the dish rack first"), "unusable");
  Reply said = read_reply(grounder(), kitchen, step, "start with the counter");
  ASSERT_TRUE(std::holds_alternative<SubtaskNamed>(said));
  EXPECT_EQ(std::get<SubtaskNamed>(said).note, "I took \"start with the counter\" as clearing the counter.");
  step.taught_subtasks = {"sort"};
  EXPECT_EQ(read(kitchen, step, "start with the counter"), "unusable");
}

// Found by fresh users (stop 40): "hmm lets start with the coffee table,
// theres a bunch of junk on it" was asked back, and "now the couch" (of a
// sofa) not understood. What the place is like, said after it, is no other
// part. ("now the couch": ReplyActsTest.APlacesSynonymNamesItWithoutAVerb.)
TEST(ReplyStructure, APlaceNamedAloneWithWhatItIsLikeOrByASynonym) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(kitchen, step, "hmm lets start with the counter, theres a bunch of junk on it"),
            "subtask clear on counter1");
  step.taught_subtasks = {"clear"};
  EXPECT_EQ(read(kitchen, step, "now the junk"), "unusable");
}

// After "What should I do with the things on the counter?" (the reason
// names the place it asks about), "clear it" and "clear" are about that
// place; without that question they are not. (The question is asked of a
// place named alone after a part whose verb is not its kind's: "sort".)
TEST(ReplyStructure, ItAfterAQuestionAboutAPlaceIsThatPlace) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  step.taught_subtasks = {"sort"};
  Reply bare = read_reply(grounder(), kitchen, step, "start with the counter");
  ASSERT_TRUE(std::holds_alternative<Unusable>(bare)) << format_reply(kitchen, bare);
  ASSERT_EQ(std::get<Unusable>(bare).topic_places.size(), 1u);
  EXPECT_EQ(kitchen.universe->name(std::get<Unusable>(bare).topic_places.front()), "counter1");
  EXPECT_EQ(read(kitchen, step, "clear it"), "unusable");
  EXPECT_EQ(read(kitchen, step, "clear"), "unusable");
  step.topic_places = std::get<Unusable>(bare).topic_places;
  EXPECT_EQ(read(kitchen, step, "clear it"), "subtask clear on counter1");
  EXPECT_EQ(read(kitchen, step, "clear"), "subtask clear on counter1");
  EXPECT_EQ(read(kitchen, step, "unload that"), "subtask unload on counter1");
  // A place named in the reply is still that place.
  EXPECT_EQ(read(kitchen, step, "clear the table"), "subtask clear on table1");
  // Several places of a kind: the question names them all, and "empty
  // them" is about them all.
  static const Scenario garage = apprentice::testing::shipped_scenario("tidy-garage");
  ReplyContext garage_step = asking(Asked::kTaskStep);
  Reply buckets = read_reply(grounder(), garage.world, garage_step, "then the buckets");
  ASSERT_TRUE(std::holds_alternative<Unusable>(buckets)) << format_reply(garage.world, buckets);
  EXPECT_EQ(std::get<Unusable>(buckets).reason, "What should I do with the things in the buckets?");
  garage_step.topic_places = std::get<Unusable>(buckets).topic_places;
  EXPECT_EQ(read(garage.world, garage_step, "empty them"), "subtask empty in bucket1 bucket2");
}

// Found in set 8: "tape measure goes in the tool box", where the world has
// a toolbox. A name of one word, said as two, is that name.
TEST(ReplyGoal, ANameSaidAsTwoWordsIsTheName) {
  const World& kitchen = kitchen30().world;
  ReplyContext plate = asking(Asked::kGoal, in(kitchen, "ceramic-plate1"));
  EXPECT_EQ(read(kitchen, plate, "in the dish washer"), "goal (in ceramic-plate1 dishwasher1)");
  EXPECT_EQ(read(kitchen, plate, "put it in the cup board"), "goal (in ceramic-plate1 cupboard1)");
  EXPECT_EQ(read(kitchen, plate, "the cup boards"), "goal (in ceramic-plate1 cupboard1)");
  // A name of two words stays two ("dish rack" is no "dishrack").
  EXPECT_EQ(read(kitchen, plate, "in the dish rack"), "goal (in ceramic-plate1 dish-rack1)");
}

// Things named in clauses of their own before the clause that says where
// they go go there too; the goal asked for is the asked thing's, and the
// others' come with it, in the order said.
TEST(ReplyGoal, ThingsListedTogetherGoTogether) {
  const World& kitchen = kitchen30().world;
  ReplyContext plate = asking(Asked::kGoal, in(kitchen, "ceramic-plate1"));
  EXPECT_EQ(read(kitchen, plate, "plates, forks and glasses go in the dishwasher"),
            "goal (in ceramic-plate1 dishwasher1); also (in metal-fork1 dishwasher1); also (in glass-tumbler1 "
            "dishwasher1)");
  EXPECT_EQ(read(kitchen, plate, "put the plates and the forks in the dishwasher and close it"),
            "goal (and (in ceramic-plate1 dishwasher1) (closed dishwasher1)); also (and (in metal-fork1 dishwasher1) "
            "(closed dishwasher1))");
  // A door said of one place is not another place's.
  EXPECT_EQ(read(kitchen, plate, "the plates go in the dishwasher and the milk goes in the fridge"),
            "goal (in ceramic-plate1 dishwasher1); also (in milk1 fridge1)");
  // A name that is the asked thing's kind and part of a place's ("cans",
  // "trash can") is the thing, in a list; a place phrase is still a place.
  static const Scenario party = apprentice::testing::shipped_scenario("party-cleanup");
  ReplyContext can = asking(Asked::kGoal, in(party.world, "soda-can1"));
  EXPECT_EQ(read(party.world, can, "cans and bottles get recycled"),
            "goal (in soda-can1 recycling-bin1); also (in beer-bottle1 recycling-bin1)");
  EXPECT_EQ(read(party.world, can, "in the can"), "goal (in soda-can1 trash-can1)");
  EXPECT_EQ(read(party.world, can, "trash can"), "goal (in soda-can1 trash-can1)");
  // Named and never placed is still asked where.
  EXPECT_EQ(read(kitchen, plate, "put the plates"), "unusable");
  // "the trash" after "in" is a place, not a verb to come.
  ReplyContext paper = asking(Asked::kGoal, in(kitchen, "paper-plate1"));
  EXPECT_EQ(read(kitchen, paper, "paper plate in the trash"), "goal (in paper-plate1 garbage1)");
}

// A task said with a time ("after the party") is named by the world's
// location (issue 21: a task's name is its verb and the world's location).
TEST(ReplyTask, ATaskSaidWithATimeIsNamedByTheLocation) {
  const World& kitchen = kitchen30().world;
  ReplyContext task = asking(Asked::kTask);
  // "clean up" is the agent's task verb "tidy" (known_verbs.h).
  EXPECT_EQ(read(kitchen, task, "clean up after the party"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "let's clean up after the party"), "task tidy kitchen");
  // Another name for a room is the location; a time said after what the
  // task is done to is not kept.
  EXPECT_EQ(read(kitchen, task, "tidy the lounge please"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "Can you put the groceries away before I leave? It's been a long day"),
            "task put away groceries");
  EXPECT_EQ(read(kitchen, task, "tidy up the kitchen"), "task tidy kitchen");
  // "back" after "got" is a particle, not the verb "to back".
  EXPECT_EQ(read(kitchen, task, "I just got back from the store, help me put the groceries away"),
            "task put away groceries");
  EXPECT_EQ(task_phrase("clean up after party"), "clean up after the party");
  EXPECT_EQ(task_phrase("tidy up kitchen"), "tidy up the kitchen");
  EXPECT_EQ(task_phrase("clean after party"), "clean after the party");
  EXPECT_EQ(task_phrase("clean after the party"), "clean after the party");
  // Found in set 8: "tidy up the cabin before we hand the boat back" was
  // "tidy back cabin"; the time said after the task holds no particle.
  EXPECT_EQ(read(kitchen, task, "tidy up the kitchen before we hand the keys back"), "task tidy kitchen");
  // A location's hyphen is said as a space ("tidy the exam-room" was said).
  EXPECT_EQ(task_phrase("tidy exam-room"), "tidy the exam room");
  EXPECT_EQ(say_task_name("tidy exam-room"), "Tidy exam room.");
}

// A request whose verb names no task ("get", "have", "end") is named by
// the verb elsewhere in it that does, over the world's location; a word
// for a building or a facility no thing here is called names the room.
TEST(ReplyTask, TheVerbThatNamesATaskWinsOverOneThatNamesNone) {
  const World& kitchen = kitchen30().world;
  ReplyContext task = asking(Asked::kTask);
  EXPECT_EQ(read(kitchen, task, "could you get the kitchen sorted before dinner"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "we had friends round, the kitchen needs cleaning"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "it's the end of the week, can you help me straighten up in here"),
            "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "make the kitchen clean again please"), "task tidy kitchen");
  // A verb that names a task of its own stays as said.
  EXPECT_EQ(read(kitchen, task, "we had a party, put the groceries away"), "task put away groceries");
  EXPECT_EQ(read(kitchen, task, "tidy up the canteen"), "task tidy kitchen");
  // Found in set 8: a boat is a vessel, the room the agent is in when it
  // names nothing here.
  EXPECT_EQ(read(kitchen, task, "clean up the boat pls"), "task tidy kitchen");
  // A place or a thing of the world is not the room: "the fridge" is not
  // taken for the kitchen.
  EXPECT_EQ(read(kitchen, task, "tidy the fridge"), "task tidy fridge");
}

// Set 8's task names (found on its first run): what happened before
// ("the kids just finished their experiment") or when ("end of the day")
// is not the task; putting everything in the room away is tidying it,
// while putting the groceries away stays a task of its own.
TEST(ReplyTask, WhatHappenedOrWhenIsNotTheTaskAndEverythingPutAwayIsTidying) {
  const World& kitchen = kitchen30().world;
  ReplyContext task = asking(Asked::kTask);
  EXPECT_EQ(read(kitchen, task, "ok so the kids just finished their experiment and i need everything put away in here"),
            "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "end of the day, can you put everything away in here?"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "put everything away"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "can you put it all away please"), "task tidy kitchen");
  EXPECT_EQ(read(kitchen, task, "Can you put the groceries away"), "task put away groceries");
  EXPECT_EQ(read(kitchen, task, "the dishes need washing"), "task wash dishes");
}

// Found by two fresh users: where a kind goes, said at the question about
// the task's steps, is that kind's goal (a correction, for the agent),
// not a part over its place; it takes a verb of placing, so that a part
// said with a place stays a part.
TEST(ReplyStructure, WhereAKindGoesSaidAtAStepIsItsGoal) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  // Before the ketchup was dealt with, it is no part over the fridge.
  EXPECT_EQ(read(kitchen, step, "the ketchup goes in the fridge").rfind("unusable", 0), 0u);
  EXPECT_EQ(read(kitchen, step, "put the mugs in the dish rack").rfind("unusable", 0), 0u);
  step.dealt_with = {in(kitchen, "ketchup1"), in(kitchen, "milk1")};
  EXPECT_EQ(read(kitchen, step, "the ketchup goes in the fridge"), "goal (in ketchup1 fridge1)");
  EXPECT_EQ(read(kitchen, step, "put the ketchup in the fridge"), "goal (in ketchup1 fridge1)");
  EXPECT_EQ(read(kitchen, step, "actually the milk goes in the fridge, not the pantry"), "goal (in milk1 fridge1)");
  EXPECT_EQ(read(kitchen, step, "clear the table"), "subtask clear on table1");
  EXPECT_EQ(read(kitchen, step, "now the counter"), "subtask clear on counter1");
}

// "cleaning stuff goes in the cabinet" and "anything frozen goes in the
// freezer, remember that" (a fresh user, stop 40) were parts "empty the
// cabinet" and "store the freezer": a verb's -ing form before a verb of
// going names things that go, and "remember" names no step.
TEST(ReplyStructure, WhereThingsGoIsNoPartForAVerbInIt) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  step.taught_subtasks = {"clear", "empty"};
  for (const char* said : {"cleaning stuff goes in the dish rack", "anything frozen goes in the fridge, remember that"})
    EXPECT_EQ(read(kitchen, step, said).rfind("subtask", 0), std::string::npos) << said << ": " << read(kitchen, step, said);
  EXPECT_EQ(read(kitchen, step, "empty the dish rack"), "subtask empty in dish-rack1");
}

// "put the teddy in the toy box", after the teddy bear was dealt with (a
// fresh user, stop 40), was a part over the toy box: a thing may be named
// by a word WordNet gives as its kind's synonym.
TEST(ReplyStructure, AThingDealtWithIsNamedByASynonymToo) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  step.dealt_with = {in(kitchen, "ketchup1")};
  EXPECT_EQ(read(kitchen, step, "put the catsup in the fridge"), "goal (in ketchup1 fridge1)");
  EXPECT_EQ(read(kitchen, step, "the catsup should go in the fridge"), "goal (in ketchup1 fridge1)");
}

// A part of the task said with a verb that names no step ("covered") gives
// way to a later clause's step verb, whose "it" is the place named before.
TEST(ReplyStructure, AStepVerbWinsOverADescriptionsVerb) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  EXPECT_EQ(read(kitchen, step, "ugh the table's covered in junk. clear it off"), read(kitchen, step, "clear the table"));
  EXPECT_EQ(read(kitchen, step, "the counter is covered in stuff, please clear it"),
            read(kitchen, step, "clear the counter"));
}

// Found teaching in the terminal: "that's it for the table", said at the
// task's next step after the table was cleared, ended the whole task with
// the counter left. A part's ending there is asked back; the task's is not.
TEST(ReplyStructure, APartsEndingAtTheTasksNextStepIsAskedBack) {
  const World& kitchen = kitchen30().world;
  ReplyContext step = asking(Asked::kTaskStep);
  Reply part = read_reply(grounder(), kitchen, step, "that's it for the table");
  ASSERT_TRUE(std::holds_alternative<Unusable>(part)) << format_reply(kitchen, part);
  EXPECT_NE(std::get<Unusable>(part).reason.find("that's all"), std::string::npos) << std::get<Unusable>(part).reason;
  EXPECT_EQ(read(kitchen, step, "the counter is clear"), "unusable");
  EXPECT_EQ(read(kitchen, step, "that's it"), "finished");
  EXPECT_EQ(read(kitchen, step, "we're done with the kitchen"), "finished");
  // Asked whether the part has more, it ends the part.
  EXPECT_EQ(read(kitchen, asking(Asked::kSubtaskEnd), "that's it for the table"), "finished");
}

// Asked whether there is more to a part: "more" or "still" without a "no"
// is more, "all clear" and "that's the lot" the end; at the task's next
// step "still" says nothing of the kind.
TEST(ReplyStructure, MoreStillAndTheLotAtTheEndOfAPart) {
  const World& kitchen = kitchen30().world;
  ReplyContext end = asking(Asked::kSubtaskEnd);
  for (std::string_view more : {"yep there's heaps more", "there's still a mug on it", "still a couple of things"})
    EXPECT_TRUE(std::holds_alternative<Proceed>(read_reply(grounder(), kitchen, end, more))) << more;
  for (std::string_view done : {"all clear", "nah that's the lot", "no more"})
    EXPECT_TRUE(std::holds_alternative<Finished>(read_reply(grounder(), kitchen, end, done))) << done;
  EXPECT_FALSE(std::holds_alternative<Proceed>(
      read_reply(grounder(), kitchen, asking(Asked::kTaskStep), "the fridge is still open")));
}

// At a proposed goal, an answer after words that carry nothing is still
// yes or no; a goal said in its place is a yes when it is the one proposed
// and a no with it as the rest otherwise; an ending is an ending. What
// says neither is asked back, and no answer is made up.
TEST(ReplyYesNo, FillersGoalsAndEndingsSaidInPlaceOfYesOrNo) {
  const World& kitchen = kitchen30().world;
  const ObjectId ketchup = in(kitchen, "ketchup1");
  ReplyContext proposed = asking(Asked::kYesNo, ketchup);
  proposed.proposal = Goal{{Literal{Fact{kitchen.vocabulary.in, {ketchup, in(kitchen, "fridge1")}}, true}}};
  auto yes_no = [&](std::string_view text) -> std::optional<YesNo> {
    Reply r = read_reply(grounder(), kitchen, proposed, text);
    if (const auto* y = std::get_if<YesNo>(&r)) return *y;
    return std::nullopt;
  };
  for (std::string_view yes : {"lol yes", "mmm yeah", "uh huh", "ugh, yes, go on"}) {
    auto answer = yes_no(yes);
    ASSERT_TRUE(answer) << yes;
    EXPECT_TRUE(answer->yes) << yes;
  }
  auto no = yes_no("hmm nope. the pantry");
  ASSERT_TRUE(no);
  EXPECT_FALSE(no->yes);
  EXPECT_EQ(no->rest, "the pantry");
  auto instead = yes_no("hold on, the ketchup goes in the pantry");
  ASSERT_TRUE(instead);
  EXPECT_FALSE(instead->yes);
  EXPECT_EQ(instead->rest, "the ketchup goes in the pantry");
  auto same = yes_no("wait, the ketchup goes in the fridge");
  ASSERT_TRUE(same);
  EXPECT_TRUE(same->yes);
  EXPECT_TRUE(std::holds_alternative<Finished>(read_reply(grounder(), kitchen, proposed, "I'm done")));
  // "ok" and "right" are fillers as well as yeses: not a yes before an
  // ending or another goal.
  EXPECT_TRUE(std::holds_alternative<Finished>(read_reply(grounder(), kitchen, proposed, "ok I'm done")));
  auto right = yes_no("right, the ketchup goes in the pantry");
  ASSERT_TRUE(right);
  EXPECT_FALSE(right->yes);
  auto ok = yes_no("ok, it goes in the fridge");
  ASSERT_TRUE(ok);
  EXPECT_TRUE(ok->yes);
  for (std::string_view unsure : {"not sure", "I don't know", "the mustard goes in the pantry"})
    EXPECT_TRUE(std::holds_alternative<Unusable>(read_reply(grounder(), kitchen, proposed, unsure))) << unsure;
  // Without a proposal (a yes/no about something else) a goal is no answer.
  EXPECT_TRUE(std::holds_alternative<Unusable>(
      read_reply(grounder(), kitchen, asking(Asked::kYesNo, ketchup), "the ketchup goes in the pantry")));
}

// Found in set 7: "yes but leave the door open" at a proposed goal was a
// bare yes; the door was lost. The rest of a yes says more of the place
// proposed; the rest of a no says where instead; a rest that repeats the
// proposal adds nothing.
TEST(ReplyYesNo, TheRestOfAYesSaysMoreOfThePlaceProposed) {
  const World& kitchen = kitchen30().world;
  const ObjectId ketchup = in(kitchen, "ketchup1");
  const ObjectId fridge = in(kitchen, "fridge1");
  ReplyContext proposed = asking(Asked::kYesNo, ketchup);
  const Literal in_fridge{Fact{kitchen.vocabulary.in, {ketchup, fridge}}, true};
  const Literal closed{Fact{kitchen.vocabulary.closed, {fridge}}, true};
  proposed.proposal = Goal{{in_fridge}};
  auto rest_of = [&](std::string_view text) -> std::optional<GoalGiven> {
    Reply r = read_reply(grounder(), kitchen, proposed, text);
    const auto* y = std::get_if<YesNo>(&r);
    if (y == nullptr) return std::nullopt;
    return goal_in_rest(grounder(), kitchen, proposed, *y);
  };
  auto shut = rest_of("yep, and close it");
  ASSERT_TRUE(shut);
  EXPECT_EQ(shut->goal, Goal({in_fridge, closed}));
  proposed.proposal = Goal{{in_fridge, closed}};
  auto open = rest_of("yes but leave the door open");
  ASSERT_TRUE(open);
  EXPECT_EQ(open->goal, Goal({in_fridge, Literal{closed.fact, false}}));
  EXPECT_FALSE(rest_of("yes, same place"));
  EXPECT_FALSE(rest_of("yes please"));
  auto instead = rest_of("no, it goes in the pantry");
  ASSERT_TRUE(instead);
  EXPECT_EQ(instead->goal.literals.front().fact.args[1], in(kitchen, "pantry1"));
}

// Found by two fresh users: things said too after a yes or a no at a
// proposed goal ("yeah, and the milk as well", "no, pantry. crackers and
// cereal too") were dropped; they get the same goal as the thing asked
// about.
TEST(ReplyYesNo, ThingsSaidTooAfterTheAnswerGetTheSameGoal) {
  const World& kitchen = kitchen30().world;
  const ObjectId ketchup = in(kitchen, "ketchup1");
  const ObjectId fridge = in(kitchen, "fridge1");
  ReplyContext proposed = asking(Asked::kYesNo, ketchup);
  proposed.proposal = Goal{{Literal{Fact{kitchen.vocabulary.in, {ketchup, fridge}}, true}}};
  proposed.still_to_come = {in(kitchen, "milk1"), in(kitchen, "cereal-box1")};
  auto rest_of = [&](std::string_view text) -> std::optional<GoalGiven> {
    Reply r = read_reply(grounder(), kitchen, proposed, text);
    const auto* y = std::get_if<YesNo>(&r);
    if (y == nullptr) return std::nullopt;
    return goal_in_rest(grounder(), kitchen, proposed, *y);
  };
  auto places_of = [&](const GoalGiven& given) {
    std::vector<std::string> out;
    for (const Goal& g : given.others) out.push_back(format_goal(*kitchen.domain, *kitchen.universe, g));
    return out;
  };
  auto yes = rest_of("yeah, and the milk as well");
  ASSERT_TRUE(yes);
  EXPECT_EQ(yes->goal, *proposed.proposal) << "the yes stands";
  EXPECT_EQ(places_of(*yes), std::vector<std::string>{"(in milk1 fridge1)"});
  auto no = rest_of("no, pantry. milk and cereal too");
  ASSERT_TRUE(no);
  EXPECT_EQ(no->goal.literals.front().fact.args[1], in(kitchen, "pantry1"));
  EXPECT_EQ(places_of(*no), (std::vector<std::string>{"(in milk1 pantry1)", "(in cereal-box1 pantry1)"}));
  // A yes with nothing said too adds nothing.
  EXPECT_FALSE(rest_of("yes please"));
}

// Found by a fresh user: "no its like the coloring book", where only a
// picture book was here, took the picture book's goal. A kind taught
// before and named whole is that kind, not a thing here named by part of
// its name.
TEST(ReplyOthers, AKindTaughtBeforeNamedWholeIsThatKind) {
  const World& kitchen = kitchen30().world;
  ASSERT_TRUE(kitchen.universe->with_category("wooden-bowl").empty());
  ReplyContext c = asking(Asked::kGoal, in(kitchen, "ketchup1"));
  auto in_place = [&](ObjectId thing, const char* place) {
    return Goal({Literal{Fact(kitchen.vocabulary.in, {thing, in(kitchen, place)}), true}});
  };
  c.goal_of_kind = [&](const std::string& kind, ObjectId thing) -> std::optional<Goal> {
    if (kind == "wooden-bowl") return in_place(thing, "pantry1");
    if (kind == "ceramic-bowl") return in_place(thing, "garbage1");
    return std::nullopt;
  };
  EXPECT_EQ(read(kitchen, c, "same as the wooden bowl"), "goal (in ketchup1 pantry1)");
  EXPECT_EQ(read(kitchen, c, "same as the ceramic bowl"), "goal (in ketchup1 garbage1)");
}

// --- References and reasons (issue 9) --------------------------------------------------

TEST(ReplyReferences, PronounsPartialNamesAndDoors) {
  const World& kitchen = kitchen30().world;
  ObjectId ketchup = in(kitchen, "ketchup1");
  ReplyContext goal = asking(Asked::kGoal, ketchup);
  EXPECT_EQ(read(kitchen, goal, "put that one in the fridge"), "goal (in ketchup1 fridge1)");
  EXPECT_EQ(read(kitchen, goal, "this goes in the pantry"), "goal (in ketchup1 pantry1)");
  // "the door" is the door of the receptacle just named, else the recent place.
  EXPECT_EQ(read(kitchen, goal, "in the pantry and shut the door"), "goal (and (in ketchup1 pantry1) (closed pantry1))");
  ReplyContext action = asking(Asked::kAction, ketchup);
  action.recent_place = in(kitchen, "dishwasher1");
  EXPECT_EQ(read(kitchen, action, "close the door"), "action (close dishwasher1)");
  EXPECT_EQ(read(kitchen, action, "close it"), "action (close dishwasher1)");
  // Partial names, when one kind of thing fits.
  ReplyContext pick = asking(Asked::kAction, in(kitchen, "milk1"));
  EXPECT_EQ(read(kitchen, pick, "pick up the pop tarts"), "action (pick-up pop-tart-box1 table1)");
  EXPECT_EQ(read(kitchen, pick, "grab the cereal"), "action (pick-up cereal-box1 table1)");
  // Two of a kind in different places: the question names both.
  Reply mug = read_reply(grounder(), kitchen, pick, "pick up the mug");
  ASSERT_TRUE(std::holds_alternative<Ambiguous>(mug)) << format_reply(kitchen, mug);
  EXPECT_EQ(std::get<Ambiguous>(mug).question, "Which do you mean: the mug on the counter or the mug in the dish rack?");
  // Two soda cans on the table: no one can tell them apart, so either will do.
  EXPECT_EQ(read(kitchen, pick, "pick up a soda can"), "action (pick-up soda-can1 table1)");
}

TEST(ReplyReasons, PlainEnglish) {
  const World& kitchen = kitchen30().world;
  ReplyContext bottle = asking(Asked::kGoal, in(kitchen, "plastic-bottle1"));
  Reply lid = read_reply(grounder(), kitchen, bottle, "put it in the recycling bin and close the lid");
  ASSERT_TRUE(std::holds_alternative<Unusable>(lid));
  EXPECT_EQ(std::get<Unusable>(lid).reason, "The recycling bin has no lid, so it can't be closed.");
  // The messages users found ungrammatical.
  Interpretation glass =
      grounder().interpret("the goal is that the glass is in the dishwasher", kitchen, std::nullopt);
  ASSERT_NE(glass.failure(), nullptr);
  EXPECT_EQ(glass.failure()->message, "I don't see a glass; do you mean the glass tumbler?");
  Interpretation shelf =
      grounder().interpret("the goal is that the ketchup is on the dish rack", kitchen, std::nullopt);
  ASSERT_NE(shelf.failure(), nullptr);
  EXPECT_EQ(shelf.failure()->message, "Things go in the dish rack, not on it.");
  Reply it = read_reply(grounder(), kitchen, asking(Asked::kGoal), "put it in the fridge");
  ASSERT_TRUE(std::holds_alternative<Unusable>(it));
  EXPECT_EQ(std::get<Unusable>(it).reason.find("the it"), std::string::npos) << std::get<Unusable>(it).reason;
  // A goal about another object is a question back, never that object's goal.
  Reply milk = read_reply(grounder(), kitchen, asking(Asked::kGoal, in(kitchen, "ketchup1")), "the milk goes in the fridge");
  ASSERT_TRUE(std::holds_alternative<Unusable>(milk));
  EXPECT_EQ(std::get<Unusable>(milk).reason, "That says what becomes of the milk, but I asked about the ketchup on the table. Where should the ketchup go?");
  // A reply quoted back keeps its commas where they were typed.
  Reply same = read_reply(grounder(), kitchen, asking(Asked::kGoal, in(kitchen, "ketchup1")), "as usual, or not");
  ASSERT_TRUE(std::holds_alternative<Unusable>(same)) << format_reply(kitchen, same);
  EXPECT_NE(std::get<Unusable>(same).reason.find("\"as usual, or not\""), std::string::npos)
      << std::get<Unusable>(same).reason;
  // "same as" a kind not taught yet says so.
  Reply cereal = read_reply(grounder(), kitchen, asking(Asked::kGoal, in(kitchen, "ketchup1")), "same as the cereal, or not");
  ASSERT_TRUE(std::holds_alternative<Unusable>(cereal)) << format_reply(kitchen, cereal);
  EXPECT_EQ(std::get<Unusable>(cereal).reason,
            "I have not learned where the cereal box goes yet. Where should the ketchup go?");
}

TEST(ReplyReasons, YesNoKeepsTheCorrection) {
  const World& kitchen = kitchen30().world;
  Reply no = read_reply(grounder(), kitchen, asking(Asked::kYesNo), "no, it goes in the pantry");
  ASSERT_TRUE(std::holds_alternative<YesNo>(no));
  EXPECT_FALSE(std::get<YesNo>(no).yes);
  EXPECT_EQ(std::get<YesNo>(no).rest, "it goes in the pantry");
}

TEST(ReplyCommands, AreReadAtEveryQuestion) {
  const World& kitchen = kitchen30().world;
  for (Asked asked : {Asked::kTask, Asked::kGoal, Asked::kYesNo}) {
    EXPECT_EQ(read(kitchen, asking(asked), "help"), "command help");
    EXPECT_EQ(read(kitchen, asking(asked), "undo that"), "command undo");
    EXPECT_EQ(read(kitchen, asking(asked), "quit"), "command quit");
    EXPECT_EQ(read(kitchen, asking(asked), "forget the glasses"), "command forget glass-tumbler");
    EXPECT_EQ(read(kitchen, asking(asked), "forget ketchup"), "command forget ketchup");
  }
}

// --- Examples that work -------------------------------------------------------------------

// Every question's examples, in both worlds, read back to an answer there.
TEST(ReplyExamples, WorkAtTheirQuestion) {
  const World& kitchen = kitchen30().world;
  for (const World* world : {&kitchen, &office()}) {
    std::vector<ReplyContext> contexts;
    for (Asked asked : {Asked::kTask, Asked::kTaskStep, Asked::kSubtaskEnd, Asked::kYesNo}) contexts.push_back(asking(asked));
    for (ObjectId id = 0; id < world->universe->size(); ++id) {
      if (world->universe->info(id).kind != ObjectKind::kItem) continue;
      contexts.push_back(asking(Asked::kGoal, id));
      contexts.push_back(asking(Asked::kAction, id));
    }
    ReplyContext which = asking(Asked::kWhich);
    which.choices = {0, 1};
    contexts.push_back(which);
    for (const ReplyContext& context : contexts) {
      std::vector<std::string> examples = example_replies(*world, context);
      EXPECT_GE(examples.size(), 2u) << to_string(context.asked);
      for (const std::string& example : examples) {
        Reply reply = read_reply(grounder(), *world, context, example);
        SCOPED_TRACE(std::string(to_string(context.asked)) + ": " + example);
        EXPECT_FALSE(std::holds_alternative<Unusable>(reply)) << std::get<Unusable>(reply).reason;
        EXPECT_FALSE(std::holds_alternative<Ambiguous>(reply));
        EXPECT_FALSE(std::holds_alternative<Command>(reply));
      }
    }
  }
  // A kind named in the plural: "the crackers go", "put them in".
  std::vector<std::string> crackers = example_replies(kitchen, asking(Asked::kGoal, in(kitchen, "crackers1")));
  ASSERT_GE(crackers.size(), 2u);
  EXPECT_TRUE(crackers[0].starts_with("the crackers go ")) << crackers[0];
  EXPECT_TRUE(crackers[1].starts_with("put them in ")) << crackers[1];
}

// --- Total and bounded ------------------------------------------------------------------------

// Whatever the words, at whatever question, a reply gets a meaning; an
// unusable one carries a reason and two examples.
RC_GTEST_PROP(ReplyProperty, TotalOnAnyWords, ()) {
  static const std::vector<std::string> kWords{
      "put", "it", "in", "the", "fridge", "and", "close", "door", "that's", "all", "done", "next", "mug", "on",
      "counter", "a", "bag", "bags", "top", "drawer", "walk", "pantry", "half", "not", "no", "yes", ",", ".",
      "away", "throw", "recycle", "clear", "table", "repeat", "while", "until", "every", "object", "is", "goes",
      "which", "one", "first", "the", "it's", "don't", "xyzzy", "of", "box", "jack", "-", "'s", "?", "with"};
  const auto length = *rc::gen::inRange(0, 30);
  std::string text;
  for (int i = 0; i < length; ++i) text += kWords[*rc::gen::inRange<std::size_t>(0, kWords.size())] + " ";
  const auto asked = *rc::gen::element(Asked::kTask, Asked::kTaskStep, Asked::kSubtaskEnd, Asked::kGoal,
                                       Asked::kAction, Asked::kYesNo, Asked::kWhich);
  const World& world = **rc::gen::element(&kitchen30().world, &office());
  ReplyContext context = asking(asked, *rc::gen::element<std::optional<ObjectId>>(std::nullopt, ObjectId{0}, ObjectId{12}));
  if (asked == Asked::kWhich) context.choices = {0, 1};
  Reply reply = read_reply(grounder(), world, context, text);
  if (const auto* unusable = std::get_if<Unusable>(&reply)) {
    RC_ASSERT(!unusable->reason.empty());
    RC_ASSERT(unusable->examples.size() >= 2u);
  }
  if (const auto* ambiguous = std::get_if<Ambiguous>(&reply)) RC_ASSERT(ambiguous->candidates.size() >= 2u);
  RC_ASSERT(!format_reply(world, reply).empty());
}

TEST(ReplyProperty, LongRepliesAreRefusedUnread) {
  std::string text(5000, 'a');
  Reply reply = read_reply(grounder(), kitchen30().world, asking(Asked::kGoal), text);
  ASSERT_TRUE(std::holds_alternative<Unusable>(reply));
}

}  // namespace
}  // namespace apprentice::language
