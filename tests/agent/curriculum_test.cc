// The curriculum's transitions (agent/curriculum.h), without a dialogue or
// a world: what comes next after each thing a teacher says, the paper's way
// (a loop announced, the first object, "is that all?", "Repeat.") and in
// everyday words (a subtask named with its place loops at once).
#include <gtest/gtest.h>

#include "agent/curriculum.h"

namespace apprentice {
namespace {

using teaching::Current;
using teaching::Curriculum;
using teaching::InProgress;
using teaching::Next;

Current clear_table() { return Current{"clear", "on", {3}}; }

void start_object(Curriculum& c, ObjectId object) { c.in_progress = InProgress{object, Goal{}, {}, State{}, {}, {}, {}}; }

TEST(Curriculum, ThePapersWayFirstObjectThenIsThatAllThenRepeat) {
  Curriculum c;
  EXPECT_EQ(c.next(true), Next::kAskTaskName);
  c.task.name = "tidy kitchen";
  EXPECT_EQ(c.next(true), Next::kAskTaskStep);
  c.announced_loop = std::vector<ObjectId>{3};  // "Repeat the following tasks while an object is on the table."
  EXPECT_EQ(c.subtask_named(clear_table()).mode, Current::Mode::kFirstObject);
  EXPECT_FALSE(c.announced_loop.has_value());
  EXPECT_EQ(c.next(true), Next::kNextObject);
  start_object(c, 7);
  EXPECT_EQ(c.next(true), Next::kAchieve);
  c.object_done();
  EXPECT_EQ(c.next(true), Next::kAskSubtaskEnd);  // "Is there more to clear on the table, or is that all?"
  c.one_was_all();                                 // "You are done."
  EXPECT_EQ(c.next(true), Next::kAskTaskStep);     // awaits "Repeat."
  c.loop();                                        // "Repeat."
  EXPECT_EQ(c.next(true), Next::kNextObject);
  start_object(c, 8);
  c.object_done();
  EXPECT_EQ(c.next(true), Next::kNextObject);  // looping: no question after each object
  c.subtask_done();
  EXPECT_FALSE(c.current.has_value());
  EXPECT_EQ(c.next(true), Next::kAskTaskStep);
  c.finishing = true;  // "You are done."
  EXPECT_EQ(c.next(true), Next::kFinish);
  EXPECT_EQ(c.evaluated_order, (std::vector<ObjectId>{7, 8}));
  EXPECT_EQ(c.objects.size(), 2u);
}

// An ending mid-part answered "yes, leave them", the paper's way: the
// things left are dealt with (each reported), the part loops no further
// and asks no "is that all?", and the asked thing is done as usual.
TEST(Curriculum, APartLeftWithThingsInItEndsOnceTheAskedThingIsDone) {
  Curriculum c;
  c.task.name = "tidy kitchen";
  c.announced_loop = std::vector<ObjectId>{3};
  c.subtask_named(clear_table());
  start_object(c, 7);
  ObjectReport left;
  left.note = "left where it is, as the instructor said";
  c.part_left(7, {{8, left}, {9, left}});
  EXPECT_EQ(c.current->mode, Current::Mode::kLoop);
  EXPECT_EQ(c.left_by_teacher, (std::vector<ObjectId>{7, 8, 9}));
  EXPECT_EQ(c.evaluated_order, (std::vector<ObjectId>{8, 9}));
  c.object_done();
  EXPECT_EQ(c.next(true), Next::kNextObject);  // none left: the session ends the part
  EXPECT_EQ(c.evaluated_order, (std::vector<ObjectId>{8, 9, 7}));
  EXPECT_EQ(c.objects.size(), 3u);
}

TEST(Curriculum, ASubtaskNamedWithItsPlaceLoopsAtOnceAndTheNextWaitsForIt) {
  Curriculum c;
  c.task.name = "tidy kitchen";
  EXPECT_EQ(c.subtask_named(clear_table()).mode, Current::Mode::kLoop);  // "clear the table"
  Current counter{"clear", "on", {4}};
  c.subtask_named(counter);  // "then the counter", before the table is done
  ASSERT_TRUE(c.queued.has_value());
  EXPECT_EQ(c.current->places, std::vector<ObjectId>{3});
  c.subtask_done();
  ASSERT_TRUE(c.current.has_value());
  EXPECT_EQ(c.current->places, std::vector<ObjectId>{4});
  EXPECT_FALSE(c.queued.has_value());
}

TEST(Curriculum, AnObjectDealtWithTwiceIsEvaluatedOnce) {
  Curriculum c;
  c.task.name = "tidy kitchen";
  c.subtask_named(clear_table());
  start_object(c, 7);
  c.object_done();
  start_object(c, 7);
  c.object_done();
  EXPECT_EQ(c.evaluated_order, std::vector<ObjectId>{7});
  EXPECT_EQ(c.objects.size(), 2u);
}

TEST(Curriculum, AKnownTaskDoesItsSubtasksAndPerformingAloneFinishesWhenNothingIsLeft) {
  Curriculum c;
  c.task = TaskKnowledge{"tidy kitchen", {LearnedSubtask{"clear", "on", "table"}}};
  c.known_to_do.assign(c.task.subtasks.begin(), c.task.subtasks.end());
  EXPECT_EQ(c.next(false), Next::kStartKnownSubtask);
  c.known_to_do.clear();
  EXPECT_EQ(c.next(false), Next::kFinish);  // alone: nothing left to do
  EXPECT_EQ(c.next(true), Next::kAskTaskStep);  // taught: what comes next?
}

}  // namespace
}  // namespace apprentice
