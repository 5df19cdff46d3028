#include "agent/lessons.h"

#include <algorithm>
#include <set>
#include <utility>

#include "util/log.h"

namespace apprentice {

void Lessons::begin(const std::string& reply, teaching::Curriculum& progress, const Knowledge& knowledge,
                    const State& world, std::size_t history) {
  // The progress without the per-object records, which only grow: copying
  // them at every lesson would cost O(objects) each time.
  std::set<ObjectId> evaluated = std::exchange(progress.evaluated, {});
  std::vector<ObjectId> evaluated_order = std::exchange(progress.evaluated_order, {});
  std::vector<ObjectReport> objects = std::exchange(progress.objects, {});
  lessons_.push_back(Lesson{reply, progress, evaluated_order.size(), objects.size(), knowledge, world, history, {}});
  progress.evaluated = std::move(evaluated);
  progress.evaluated_order = std::move(evaluated_order);
  progress.objects = std::move(objects);
}

void Lessons::record(StoreWrite write) {
  if (!lessons_.empty()) lessons_.back().writes.push_back(std::move(write));
}

Status Lessons::learn_goal(Knowledge& knowledge, const GoalKnowledge& goal) {
  std::optional<GoalKnowledge> previous;
  if (const GoalKnowledge* known = knowledge.goals.find(goal.key)) previous = *known;
  knowledge.goals.add(goal);
  if (!store_) return {};
  if (auto s = store_->save_goal(goal); !s) return s;
  // Durable from here (the fleet's kill test reads these lines: a goal
  // logged saved must be in the store, whatever befalls the process).
  std::string saved = format_goal_knowledge(goal);
  std::replace(saved.begin(), saved.end(), '\n', ' ');
  spdlog::debug("goal saved: {}", saved);
  StoreWrite write;
  write.kind = StoreWrite::Kind::kGoal;
  write.goal_key = goal.key;
  write.previous_goal = std::move(previous);
  record(std::move(write));
  return {};
}

Result<bool> Lessons::learn_rule(Knowledge& knowledge, Rule rule) {
  Rule kept = rule;
  if (!knowledge.rules.add(*domain_, std::move(rule))) return false;
  if (!store_) return true;
  if (auto s = store_->save_rule(*domain_, kept); !s) return tl::unexpected(s.error());
  StoreWrite write;
  write.kind = StoreWrite::Kind::kRule;
  write.rule = std::move(kept);
  record(std::move(write));
  return true;
}

Status Lessons::learn_task(Knowledge& knowledge, const TaskKnowledge& task) {
  auto& tasks = knowledge.tasks;
  auto existing = std::find_if(tasks.begin(), tasks.end(), [&](const TaskKnowledge& t) { return t.name == task.name; });
  std::optional<TaskKnowledge> previous;
  if (existing == tasks.end()) {
    tasks.push_back(task);
  } else {
    previous = *existing;
    *existing = task;
  }
  if (!store_) return {};
  if (auto s = store_->save_task(task); !s) return s;
  StoreWrite write;
  write.kind = StoreWrite::Kind::kTask;
  write.task_name = task.name;
  write.previous_task = std::move(previous);
  record(std::move(write));
  return {};
}

Status Lessons::learn_class_rule(Knowledge& knowledge, const ClassRule& rule) {
  knowledge.class_rules.add(rule);
  knowledge.forgotten_rules.remove(rule);
  StoreWrite write;
  write.kind = StoreWrite::Kind::kClassRule;
  write.class_rule = rule;
  record(std::move(write));
  if (!store_) return {};
  return store_->save_class_rule(rule);
}

Status Lessons::forget_goal(Knowledge& knowledge, const GoalKey& key) {
  const GoalKnowledge* known = knowledge.goals.find(key);
  if (known == nullptr) return {};
  StoreWrite write;
  write.kind = StoreWrite::Kind::kForgottenGoal;
  write.goal_key = key;
  write.previous_goal = *known;
  knowledge.goals.remove(key);
  // Recorded with no store too: undo names what it brings back.
  record(std::move(write));
  if (!store_) return {};
  return store_->remove_goal(key);
}

void Lessons::forget_class_rule(const ClassRule& rule) {
  for (Lesson& lesson : lessons_) {
    lesson.knowledge.class_rules.remove(rule);
    lesson.knowledge.forgotten_rules.add(rule);
  }
}

Result<std::optional<Lessons::Undone>> Lessons::undo(teaching::Curriculum& progress, Knowledge& knowledge) {
  if (lessons_.empty()) return std::nullopt;
  Lesson lesson = std::move(lessons_.back());
  lessons_.pop_back();
  Undone undone{lesson.reply, {}, {}, std::move(lesson.world), lesson.history};
  for (const StoreWrite& write : lesson.writes)
    if (write.kind == StoreWrite::Kind::kClassRule) undone.class_rules.push_back(*write.class_rule);
    else if (write.kind == StoreWrite::Kind::kForgottenGoal) undone.remembered.push_back(write.goal_key);
  for (auto write = lesson.writes.rbegin(); store_ != nullptr && write != lesson.writes.rend(); ++write) {
    Status status;
    switch (write->kind) {
      case StoreWrite::Kind::kGoal:
        status = write->previous_goal ? store_->save_goal(*write->previous_goal) : store_->remove_goal(write->goal_key);
        break;
      case StoreWrite::Kind::kForgottenGoal: status = store_->save_goal(*write->previous_goal); break;
      case StoreWrite::Kind::kRule: status = store_->remove_rule(*domain_, *write->rule); break;
      case StoreWrite::Kind::kTask:
        status = write->previous_task ? store_->save_task(*write->previous_task) : store_->remove_task(write->task_name);
        break;
      case StoreWrite::Kind::kClassRule: status = store_->remove_class_rule(*write->class_rule); break;
    }
    if (!status) return tl::unexpected(status.error());
  }
  knowledge = std::move(lesson.knowledge);
  // Back to the progress before the lesson: its records are those of now,
  // cut to their sizes then.
  std::set<ObjectId> evaluated = std::move(progress.evaluated);
  std::vector<ObjectId> evaluated_order = std::move(progress.evaluated_order);
  std::vector<ObjectReport> objects = std::move(progress.objects);
  for (std::size_t i = lesson.evaluated_count; i < evaluated_order.size(); ++i) evaluated.erase(evaluated_order[i]);
  evaluated_order.resize(lesson.evaluated_count);
  objects.resize(lesson.objects_count);
  progress = std::move(lesson.progress);
  progress.evaluated = std::move(evaluated);
  progress.evaluated_order = std::move(evaluated_order);
  progress.objects = std::move(objects);
  return undone;
}

}  // namespace apprentice
