#include "agent/curriculum.h"

#include <algorithm>
#include <utility>

namespace apprentice::teaching {

Next Curriculum::next(bool learning) const {
  if (in_progress) return Next::kAchieve;
  if (task.name.empty()) return Next::kAskTaskName;
  if (current) {
    switch (current->mode) {
      case Current::Mode::kEndQuestion: return Next::kAskSubtaskEnd;
      case Current::Mode::kAwaitRepeat: return Next::kAskTaskStep;
      case Current::Mode::kFirstObject:
      case Current::Mode::kLoop: return Next::kNextObject;
    }
  }
  if (!known_to_do.empty()) return Next::kStartKnownSubtask;
  if (finishing || !learning) return Next::kFinish;
  return Next::kAskTaskStep;
}

Current Curriculum::subtask_named(Current subtask) {
  subtask.mode = announced_loop ? Current::Mode::kFirstObject : Current::Mode::kLoop;
  announced_loop.reset();
  if (current) {
    current->mode = Current::Mode::kLoop;
    queued = subtask;
  } else {
    current = subtask;
  }
  return subtask;
}

void Curriculum::one_was_all() { current->mode = Current::Mode::kAwaitRepeat; }

void Curriculum::loop() { current->mode = Current::Mode::kLoop; }

void Curriculum::object_done() {
  InProgress& work = *in_progress;
  if (evaluated.insert(work.object).second) evaluated_order.push_back(work.object);
  objects.push_back(work.report);
  in_progress.reset();
  if (current && current->mode == Current::Mode::kFirstObject) current->mode = Current::Mode::kEndQuestion;
}

void Curriculum::thing_left(ObjectId object) { left_by_teacher.push_back(object); }

std::vector<ObjectId> Curriculum::dealt_with_like(const World& world, ObjectId thing,
                                                  const std::vector<std::string>& properties) const {
  const std::string& kind = world.universe->info(thing).category;
  std::vector<ObjectId> out;
  for (ObjectId o : evaluated_order) {
    const ObjectInfo& other = world.universe->info(o);
    if (other.category == kind && std::all_of(properties.begin(), properties.end(), [&](const std::string& p) {
          return std::find(other.properties.begin(), other.properties.end(), p) != other.properties.end();
        }))
      out.push_back(o);
  }
  return out;
}

bool Curriculum::still_to_come(const World& world, ObjectId item) const {
  if (!current || evaluated.count(item)) return false;
  const Vocabulary& v = world.vocabulary;
  for (ObjectId place : current->places)
    for (PredicateId relation : {v.on, v.in})
      if (world.state.holds(Fact(relation, {item, place}))) return true;
  return false;
}

void Curriculum::part_left(ObjectId asked, const std::vector<std::pair<ObjectId, ObjectReport>>& left) {
  thing_left(asked);
  for (const auto& [object, report] : left) {
    if (!evaluated.insert(object).second) continue;
    evaluated_order.push_back(object);
    objects.push_back(report);
    left_by_teacher.push_back(object);
  }
  if (current) current->mode = Current::Mode::kLoop;
}

void Curriculum::subtask_done() {
  current = std::move(queued);
  queued.reset();
}

}  // namespace apprentice::teaching
