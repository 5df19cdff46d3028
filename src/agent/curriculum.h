// Internal to the agent: the curriculum of one run, how far its teaching
// has come: the task, the subtask under way and its mode, the object being
// worked on, and what was done. A value, so that a lesson (agent/lessons.h)
// can keep a copy and "undo" can put it back; with its transitions, so that
// what comes next is read from it alone, without a dialogue or a world
// (tests/agent/curriculum_test.cc). The session (agent/session.h) asks it
// what comes next, does that, and tells it what happened.
//
//   next()               what the state asks for           what moves it on
//   kAchieve             an object whose goal is known     object_done()
//   kAskTaskName         no task yet                       (the session names it)
//   kNextObject          a subtask under way, looping or   object_done(), subtask_done(),
//                        at its first object               part_left()
//   kAskSubtaskEnd       the paper's way, after the first  one_was_all(), loop(),
//                        object: "is that all?"            subtask_named()
//   kAskTaskStep         a loop that awaits "Repeat.", or  loop(), subtask_named(),
//                        no subtask under way              (finishing)
//   kStartKnownSubtask   a known task's subtasks to do     (the session starts one)
//   kFinish              finishing, or performing alone    (finished)
//                        with nothing left
#pragma once

#include <deque>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "agent/report.h"
#include "knowledge/goal_memory.h"
#include "knowledge/task_knowledge.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/world.h"

namespace apprentice::teaching {

// The subtask being worked on, and how far: the paper's way (a loop
// announced first) does one object, asks whether the subtask is done, and
// loops once told "Repeat."; a subtask named with its place alone loops
// over its places' objects at once.
struct Current {
  enum class Mode { kFirstObject, kEndQuestion, kAwaitRepeat, kLoop };
  std::string verb;
  std::string relation;  // "on" or "in"
  std::vector<ObjectId> places;
  Mode mode = Mode::kLoop;
};

// An object whose goal is known, being achieved.
struct InProgress {
  ObjectId object = 0;
  Goal goal;
  ObjectReport report;
  State start;  // the world when its actions began
  std::vector<Action> actions;         // executed towards the goal
  std::vector<std::string> sources;    // where each came from
  std::vector<std::string> llm_steps;  // the steps as the LLM prompt shows them
};

// What comes next (Curriculum::next).
enum class Next { kAchieve, kAskTaskName, kNextObject, kAskSubtaskEnd, kAskTaskStep, kStartKnownSubtask, kFinish };

// How far the teaching has come.
struct Curriculum {
  TaskKnowledge task;
  std::optional<Current> current;
  std::optional<Current> queued;                        // named before the current subtask ended
  std::optional<std::vector<ObjectId>> announced_loop;  // "Repeat ... while an object is on the table."
  std::deque<LearnedSubtask> known_to_do;               // a known task's subtasks still to do
  bool asked_about_task = false;  // the task-step question was asked at least once
  bool finishing = false;         // the teacher said the task is done; the current loop ends first
  bool finished = false;
  // evaluated, objects and evaluated_order only grow (a lesson keeps their
  // sizes, not copies: see Lessons::begin).
  std::set<ObjectId> evaluated;
  std::vector<ObjectId> evaluated_order;  // evaluated, in the order inserted
  std::optional<InProgress> in_progress;
  // The things the teacher said to leave (part_left, thing_left): not
  // things the agent failed to deal with.
  std::vector<ObjectId> left_by_teacher;
  // The things the teacher had put somewhere for this time only ("the
  // blanket goes on the sofa, its cold tonight"): where they are was said,
  // and not learned.
  std::vector<ObjectId> placed_this_time;
  std::vector<ObjectReport> objects;
  int goals_learned = 0;
  int rules_learned = 0;
  // The goal the last object was given, learned or remembered: what "socks
  // too" and "same again" mean.
  std::optional<GoalKey> last_goal;
  // The places the teacher wants left open from now on ("leave the washer
  // open from now on"), by door_key (agent/goal_repair.h): never closed by
  // the norm.
  std::set<std::string> doors_left_open;

  // What comes next; `learning`: a teacher is teaching (else the agent
  // performs alone and finishes when nothing is left).
  Next next(bool learning) const;
  // A subtask named: it runs object by object after a loop was announced
  // (the paper's way: the first object, then "is that all?"), else it
  // loops at once. Named while another is under way, it waits until that
  // one's loop is done. Returns it as it will run.
  Current subtask_named(Current subtask);
  // The teacher's answers about the subtask under way: one thing was all
  // (the loop then waits for "Repeat."); loop over the rest.
  void one_was_all();
  void loop();
  // The object being worked on is dealt with: recorded (once in
  // `evaluated`); after the paper's first object comes "is that all?".
  void object_done();
  // The subtask under way has nothing left: the one named meanwhile, if any,
  // begins.
  void subtask_done();
  // The teacher ended the part under way with things still in it (an
  // ending at a goal question, then "yes" to "Shall I leave them?"): each
  // of `left` is dealt with, left where it is (with its report, which
  // says so), and the part loops no further, so that it ends once the
  // object being asked about is done.
  // `asked`, the object asked about, is left too; its report comes when
  // it is done (object_done).
  void part_left(ObjectId asked, const std::vector<std::pair<ObjectId, ObjectReport>>& left);
  // The teacher said to leave `object` ("leave it"): its report comes when
  // it is done; it is not a thing the agent failed to deal with.
  void thing_left(ObjectId object);

  // Whether `item` is in or on a place of the subtask under way and not yet
  // dealt with (false with none under way): a goal said for it now is used
  // when it comes.
  bool still_to_come(const World& world, ObjectId item) const;
  // The things of `thing`'s kind already dealt with, in order, with every
  // one of `properties` ("clean"): what a correction of `thing` moves.
  std::vector<ObjectId> dealt_with_like(const World& world, ObjectId thing,
                                        const std::vector<std::string>& properties) const;
};

}  // namespace apprentice::teaching
