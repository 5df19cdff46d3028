#include "instructor/simulated_instructor.h"

#include <algorithm>
#include <cctype>

#include "instructor/dialogue.h"
#include "language/generation.h"
#include "language/narration.h"
#include "search/iterative_deepening.h"

namespace apprentice {

namespace {

// Deep enough for any kitchen goal: open, pick up, put, close, plus putting
// down whatever is in hand first.
constexpr int kInstructorSearchDepth = 8;

bool has_objects_at(const World& world, const std::vector<ObjectId>& places) {
  for (ObjectId place : places)
    for (PredicateId relation : {world.vocabulary.on, world.vocabulary.in})
      if (!world.state.facts_with_second(relation, 2, place).empty()) return true;
  return false;
}

}  // namespace

std::optional<int> shortest_plan_length(const World& world, const State& state, const Goal& goal,
                                        int max_depth) {
  SearchOptions options;
  options.max_depth = max_depth;
  PlanResult result = find_plan(*world.domain, *world.universe, state, goal, options);
  if (result.status != SearchStatus::kSolved) return std::nullopt;
  return static_cast<int>(result.plan.size());
}

SimulatedInstructor::SimulatedInstructor(Scenario scenario) : scenario_(std::move(scenario)) {}

Result<std::string> SimulatedInstructor::answer(const Question& question, const World& world) {
  switch (question.kind) {
    case QuestionKind::kTaskName: return language::say_task_name(scenario_.task.name);
    case QuestionKind::kTaskStep: return next_task_step(world);
    case QuestionKind::kSubtaskStep: return goal_or_done(question, world);
    case QuestionKind::kNextAction: return next_action(question, world);
    case QuestionKind::kConfirmGoal: return std::string(accepts_goal(question, world) ? "yes." : "no.");
    case QuestionKind::kConfirmAction: return std::string(accepts_action(question, world) ? "yes." : "no.");
    case QuestionKind::kWhich: return which(question, world);
    // The script says no ending mid-part, so it never leaves things.
    case QuestionKind::kConfirm: return std::string("no.");
  }
  return std::string("You are done.");
}

std::string SimulatedInstructor::next_task_step(const World& now) {
  for (;;) {
    if (subtask_index_ >= scenario_.task.subtasks.size()) return "You are done.";
    const Subtask& subtask = scenario_.task.subtasks[subtask_index_];
    const World& world = scenario_.world;
    switch (phase_) {
      case Phase::kAnnounceLoop:
        // A subtask whose place is already empty (an agent that knew the
        // task has done it) is not taught.
        if (!has_objects_at(now, subtask.places)) {
          ++subtask_index_;
          continue;
        }
        phase_ = Phase::kAnnounceSubtask;
        return language::say_repeat_while(world, subtask.places);
      case Phase::kAnnounceSubtask:
        phase_ = Phase::kRepeat;
        return language::say_subtask(subtask.verb, world, subtask.places);
      case Phase::kRepeat:
        phase_ = Phase::kNextSubtask;
        return "Repeat.";
      case Phase::kNextSubtask:
        ++subtask_index_;
        phase_ = Phase::kAnnounceLoop;
        continue;
    }
  }
}

std::optional<Goal> SimulatedInstructor::wanted_goal(const Question& question, const World& world) const {
  (void)world;  // the scenario's objects are the world's
  if (!question.object) return std::nullopt;
  return scenario_.intended_goal(question.subtask, *question.object);
}

std::string SimulatedInstructor::goal_or_done(const Question& question, const World& world) const {
  // The agent asks this about an object, to learn its goal, and about the
  // subtask alone once it has done it, to learn where the subtask ends.
  if (!question.object) return language::say_done();
  auto goal = wanted_goal(question, world);
  if (!goal || goal->satisfied_by(world.state)) return language::say_done();
  return language::describe_goal_instruction(world, *question.object, *goal);
}

std::string SimulatedInstructor::next_action(const Question& question, const World& world) const {
  auto goal = wanted_goal(question, world);
  if (!goal) return "You are done.";
  SearchOptions options;
  options.max_depth = kInstructorSearchDepth;
  PlanResult plan = find_plan(*world.domain, *world.universe, world.state, *goal, options);
  if (plan.status != SearchStatus::kSolved || plan.plan.empty()) return "You are done.";
  return language::describe_action(world, plan.plan.front());
}

std::string SimulatedInstructor::which(const Question& question, const World& world) const {
  // The place the instructor wants the object in, if it is offered; else
  // the first thing offered.
  if (question.choices.empty()) return "You are done.";
  ObjectId chosen = question.choices.front();
  if (question.object) {
    if (const IntentEntry* entry = scenario_.intent_for(question.subtask, *question.object)) {
      for (ObjectId c : question.choices)
        if (c == entry->place) chosen = c;
    }
  }
  return language::spoken_name(world, chosen);
}

bool SimulatedInstructor::accepts_goal(const Question& question, const World& world) const {
  auto wanted = wanted_goal(question, world);
  if (!wanted || !question.goal || *wanted != *question.goal) return false;
  // The things asked about together: each must go where the object does,
  // by the same goal said of it.
  for (ObjectId other : question.together) {
    std::vector<Literal> literals = question.goal->literals;
    for (Literal& l : literals)
      for (std::size_t i = 0; i < l.fact.arity; ++i)
        if (l.fact.args[i] == *question.object) l.fact.args[i] = other;
    auto its = scenario_.intended_goal(question.subtask, other);
    if (!its || *its != Goal(std::move(literals))) return false;
  }
  return true;
}

bool SimulatedInstructor::accepts_action(const Question& question, const World& world) const {
  auto wanted = wanted_goal(question, world);
  if (!wanted || !question.action) return false;
  if (!is_applicable(*world.domain, world.state, *question.action)) return false;
  auto now = shortest_plan_length(world, world.state, *wanted, kInstructorSearchDepth);
  if (!now || *now == 0) return false;
  State after = apply(*world.domain, world.state, *question.action);
  auto then = shortest_plan_length(world, after, *wanted, *now - 1);
  return then && *then == *now - 1;
}

}  // namespace apprentice
