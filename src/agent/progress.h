// Internal to the agent: how far one run's teaching has come (the state a
// step of the session reads and changes, agent/session.h), as plain values,
// so that a lesson (agent/lessons.h) can keep a copy and "undo" can put it
// back.
#pragma once

#include <deque>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "agent/report.h"
#include "knowledge/goal_memory.h"
#include "knowledge/task_knowledge.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/state.h"

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

// How far the teaching has come.
struct Progress {
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
  std::vector<ObjectReport> objects;
  int goals_learned = 0;
  int rules_learned = 0;
  // The goal the last object was given, learned or remembered: what "socks
  // too" and "same again" mean.
  std::optional<GoalKey> last_goal;
};

}  // namespace apprentice::teaching
