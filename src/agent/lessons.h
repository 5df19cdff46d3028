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
// are lent to each call.
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

  // Writes to the store (none without one), each kept in the open lesson
  // with what it replaced, so that undo can revert it.
  Status store_goal(const GoalKnowledge& goal, std::optional<GoalKnowledge> previous);
  Status store_rule(const Rule& rule);
  Status store_task(const TaskKnowledge& task, std::optional<TaskKnowledge> previous);
  // A person's rule: kept in the open lesson even without a store (undo
  // takes it out of the session's rules too), then written.
  Status store_class_rule(const ClassRule& rule);

  // What is forgotten for good ("forget ketchup", "forget fruit"): no undo
  // may bring it back, so every lesson's knowledge forgets it too.
  void forget_goal(const GoalKey& key);
  void forget_class_rule(const ClassRule& rule);

  // What undoing a lesson leaves for the session to do: say what is
  // forgotten, take the person's rules said in it out of its own, and put
  // the world back as it was (by acting).
  struct Undone {
    std::string reply;
    std::vector<ClassRule> class_rules;  // the person's rules said in the lesson
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
    enum class Kind { kGoal, kRule, kTask, kClassRule } kind = Kind::kGoal;
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
