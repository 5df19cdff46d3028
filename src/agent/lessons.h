// Internal to the agent: the teacher's lessons of one session, and undo.
//
// Each reply that teaches the agent something opens a lesson, which keeps
// the progress (agent/curriculum.h) and the knowledge as they were before it,
// with the world and how many actions had been taken, and every write to
// the store until the next lesson. Undoing the last lesson reverts those
// writes, latest first, and puts the progress and the knowledge back; the
// session (agent/session.h) then says so and puts the world back by acting.
//
// Lessons is passed only what it needs: the store (borrowed, may be null)
// and the domain its rules are written in; the progress and the knowledge
// are lent to each call. What a lesson teaches reaches the knowledge and
// the store through Lessons alone (learn_goal, ...), so that no write can
// miss its lesson.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "agent/curriculum.h"
#include "knowledge/preferences.h"
#include "knowledge/store.h"
#include "knowledge/store_engine.h"
#include "util/result.h"
#include "world/state.h"

namespace apprentice {

class Lessons {
 public:
  // `store` (null: nothing is kept) and `domain` are borrowed and must
  // outlive the lessons.
  Lessons(KnowledgeStore* store, const Domain& domain) : store_(store), domain_(&domain) {}

  // Opens a lesson for `reply`, keeping `progress` and `knowledge` as they
  // are, the world `world` and the `history` actions taken so far. The
  // records that only grow (the objects evaluated and reported) are kept
  // as their sizes, not copied.
  void begin(const std::string& reply, teaching::Curriculum& progress, const Knowledge& knowledge, const State& world,
             std::size_t history);

  bool empty() const { return lessons_.empty(); }
  // The reply of the last lesson; null when there is none.
  const std::string* last_reply() const { return lessons_.empty() ? nullptr : &lessons_.back().reply; }

  // What a reply teaches, kept in one call each: into `knowledge`, into the
  // store (none without one), and into the open lesson with what it
  // replaced, so that undo reverts the write. The knowledge changes first:
  // when the store fails (the error is returned) the session still has it.
  Status learn_goal(Knowledge& knowledge, const GoalKnowledge& goal);
  // false, and nothing written, when `knowledge` holds the rule already.
  Result<bool> learn_rule(Knowledge& knowledge, Rule rule);
  Status learn_task(Knowledge& knowledge, const TaskKnowledge& task);
  // A person's rule, no longer forgotten: kept in the open lesson even
  // without a store (undo names it, for the session to take it out of the
  // rules said), then written.
  Status learn_class_rule(Knowledge& knowledge, const ClassRule& rule);

  // "forget ketchup": the goal taken out of `knowledge` and the store, in
  // the open lesson (which the session opens for the forget itself), so
  // that an undo right after brings it back; undoing further back, past
  // the forget, goes on from there as with any lesson.
  Status forget_goal(Knowledge& knowledge, const GoalKey& key);
  // A person's rule forgotten for good ("forget fruit"): no undo may bring
  // it back, so every lesson's knowledge forgets it too.
  void forget_class_rule(const ClassRule& rule);

  // What undoing a lesson leaves for the session to do: say what is
  // forgotten, take the person's rules said in it out of its own, and put
  // the world back as it was (by acting).
  struct Undone {
    std::string reply;
    std::vector<ClassRule> class_rules;  // the person's rules said in the lesson
    std::vector<GoalKey> remembered;     // the goals the lesson forgot, known again
    State world;
    std::size_t history = 0;
  };
  // Undoes the last lesson: reverts its writes to the store, latest first,
  // and puts `progress` (its growing records cut back to their sizes then)
  // and `knowledge` back. nullopt when there is no lesson. Errors: the
  // store's, when a write cannot be reverted (the lesson is gone then).
  Result<std::optional<Undone>> undo(teaching::Curriculum& progress, Knowledge& knowledge);

 private:
  struct StoreWrite {
    // kGoal: a goal learned (previous_goal: the one it replaced);
    // kForgottenGoal: a goal forgotten (previous_goal: the goal).
    enum class Kind { kGoal, kForgottenGoal, kRule, kTask, kClassRule } kind = Kind::kGoal;
    GoalKey goal_key;
    std::optional<GoalKnowledge> previous_goal;
    std::optional<Rule> rule;
    std::optional<ClassRule> class_rule;  // a person's rule, said in the lesson
    std::optional<TaskKnowledge> previous_task;
    std::string task_name;
  };
  struct Lesson {
    std::string reply;
    teaching::Curriculum progress;  // without evaluated, evaluated_order and objects: their sizes are below
    std::size_t evaluated_count = 0;
    std::size_t objects_count = 0;
    Knowledge knowledge;
    State world;
    std::size_t history = 0;
    std::vector<StoreWrite> writes;
  };
  void record(StoreWrite write);

  KnowledgeStore* store_;
  const Domain* domain_;
  std::vector<Lesson> lessons_;  // oldest first
};

}  // namespace apprentice
