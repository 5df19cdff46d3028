// Lessons and undo. Each reply that teaches the agent something opens a
// lesson, which keeps the progress, the knowledge and the world as they
// were before it, and every write to the store until the next lesson.
// "undo" forgets the last lesson: it reverts those writes, restores the
// knowledge and the progress, and puts the world back by acting (the world
// changes only through the simulator), so the question that lesson
// answered comes again.
#include <algorithm>
#include <set>
#include <utility>

#include "agent/session.h"
#include "language/narration.h"
#include "search/iterative_deepening.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// Deep enough to undo any one action of the kitchen (at most: put down
// what is in hand, open, take out, close).
constexpr int kPutBackDepth = 4;

// The literals that turn `now` into `target`.
Goal difference(const State& now, const State& target) {
  std::vector<Literal> literals;
  for (const Fact& f : target.facts())
    if (!now.holds(f)) literals.push_back(Literal{f, true});
  for (const Fact& f : now.facts())
    if (!target.holds(f)) literals.push_back(Literal{f, false});
  return Goal(std::move(literals));
}

}  // namespace

void TaskLearningAgent::Session::begin_lesson(const std::string& reply) {
  if (!learning_ || dialogue_ == nullptr) return;
  // The progress without the per-object records, which only grow: copying
  // them at every lesson would cost O(objects) each time.
  std::set<ObjectId> evaluated = std::exchange(progress_.evaluated, {});
  std::vector<ObjectId> evaluated_order = std::exchange(progress_.evaluated_order, {});
  std::vector<ObjectReport> objects = std::exchange(progress_.objects, {});
  lessons_.push_back(Lesson{reply, progress_, evaluated_order.size(), objects.size(), agent_.knowledge_,
                            world().state, simulator_.history().size(), {}});
  progress_.evaluated = std::move(evaluated);
  progress_.evaluated_order = std::move(evaluated_order);
  progress_.objects = std::move(objects);
}

Status TaskLearningAgent::Session::store_goal(const GoalKnowledge& goal, std::optional<GoalKnowledge> previous) {
  if (!agent_.store_) return {};
  if (auto s = agent_.store_->save_goal(goal); !s) return s;
  // Durable from here (the fleet's kill test reads these lines: a goal
  // logged saved must be in the store, whatever befalls the process).
  std::string saved = format_goal_knowledge(goal);
  std::replace(saved.begin(), saved.end(), '\n', ' ');
  spdlog::debug("goal saved: {}", saved);
  if (!lessons_.empty()) {
    StoreWrite write;
    write.kind = StoreWrite::Kind::kGoal;
    write.goal_key = goal.key;
    write.previous_goal = std::move(previous);
    lessons_.back().writes.push_back(std::move(write));
  }
  return {};
}

Status TaskLearningAgent::Session::store_rule(const Rule& rule) {
  if (!agent_.store_) return {};
  if (auto s = agent_.store_->save_rule(*world().domain, rule); !s) return s;
  if (!lessons_.empty()) {
    StoreWrite write;
    write.kind = StoreWrite::Kind::kRule;
    write.rule = rule;
    lessons_.back().writes.push_back(std::move(write));
  }
  return {};
}

Status TaskLearningAgent::Session::store_task(std::optional<TaskKnowledge> previous) {
  if (!agent_.store_) return {};
  if (auto s = agent_.store_->save_task(progress_.task); !s) return s;
  if (!lessons_.empty()) {
    StoreWrite write;
    write.kind = StoreWrite::Kind::kTask;
    write.task_name = progress_.task.name;
    write.previous_task = std::move(previous);
    lessons_.back().writes.push_back(std::move(write));
  }
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::undo() {
  if (lessons_.empty()) {
    say("There is nothing to undo yet.", Voice::kResponse);
    return {};
  }
  Lesson lesson = std::move(lessons_.back());
  lessons_.pop_back();
  KnowledgeStore* store = agent_.store_;
  for (const StoreWrite& write : lesson.writes)
    if (write.kind == StoreWrite::Kind::kClassRule) said_rules_.remove(*write.class_rule);
  for (auto write = lesson.writes.rbegin(); store != nullptr && write != lesson.writes.rend(); ++write) {
    Status status;
    switch (write->kind) {
      case StoreWrite::Kind::kGoal:
        status = write->previous_goal ? store->save_goal(*write->previous_goal) : store->remove_goal(write->goal_key);
        break;
      case StoreWrite::Kind::kRule: status = store->remove_rule(*world().domain, *write->rule); break;
      case StoreWrite::Kind::kTask:
        status = write->previous_task ? store->save_task(*write->previous_task) : store->remove_task(write->task_name);
        break;
      case StoreWrite::Kind::kClassRule: status = store->remove_class_rule(*write->class_rule); break;
    }
    if (!status) return stop(status.error());
  }
  agent_.knowledge_ = std::move(lesson.knowledge);
  // Back to the progress before the lesson: its records are those of now,
  // cut to their sizes then.
  std::set<ObjectId> evaluated = std::move(progress_.evaluated);
  std::vector<ObjectId> evaluated_order = std::move(progress_.evaluated_order);
  std::vector<ObjectReport> objects = std::move(progress_.objects);
  for (std::size_t i = lesson.evaluated_count; i < evaluated_order.size(); ++i) evaluated.erase(evaluated_order[i]);
  evaluated_order.resize(lesson.evaluated_count);
  objects.resize(lesson.objects_count);
  progress_ = std::move(lesson.progress);
  progress_.evaluated = std::move(evaluated);
  progress_.evaluated_order = std::move(evaluated_order);
  progress_.objects = std::move(objects);
  say(with_period("I forgot what you told me last: \"" + lesson.reply + "\""), Voice::kResponse);
  put_world_back(lesson.world, lesson.history);
  return tl::unexpected(Stop{});
}

void TaskLearningAgent::Session::put_world_back(const State& before, std::size_t history_size) {
  const Domain& domain = *world().domain;
  const std::vector<Action>& history = simulator_.history();
  if (history.size() <= history_size) return;
  std::vector<State> states{before};
  for (std::size_t i = history_size; i < history.size(); ++i) states.push_back(apply(domain, states.back(), history[i]));
  std::vector<Action> undoing;
  // Each action is undone in turn, latest first: each is a short search.
  for (std::size_t i = states.size() - 1; i-- > 0;) {
    Goal back = difference(world().state, states[i]);
    if (back.empty()) continue;
    SearchOptions options;
    options.max_depth = kPutBackDepth;
    PlanResult plan = find_plan(domain, *world().universe, world().state, back, options);
    bool done = plan.status == SearchStatus::kSolved;
    for (const Action& action : plan.plan) {
      if (!done || !execute(action)) {
        done = false;
        break;
      }
      undoing.push_back(action);
    }
    if (!done) {
      if (!undoing.empty()) say("To put things back, " + language::report_actions(world(), undoing), Voice::kResponse);
      say("I could not put everything back as it was.", Voice::kResponse);
      return;
    }
  }
  std::string report = language::report_actions(world(), undoing);
  if (!report.empty()) say("To put things back as they were, " + report, Voice::kResponse);
}

}  // namespace apprentice
