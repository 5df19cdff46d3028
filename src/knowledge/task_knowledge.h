// Task-structure knowledge: what the instructor taught the task to be. For
// "tidy kitchen": while an object is on the table, clear it; then while an
// object is on the counter, store it; and so on. Places are kept by
// category, so the structure applies in any kitchen with such places.
#pragma once

#include <string>
#include <vector>

namespace apprentice {

struct LearnedSubtask {
  std::string verb;            // "clear"
  std::string relation;        // "on" or "in": where the objects are
  std::string place_category;  // "table"
  friend bool operator==(const LearnedSubtask&, const LearnedSubtask&) = default;
};

struct TaskKnowledge {
  std::string name;  // "tidy kitchen"
  std::vector<LearnedSubtask> subtasks;
  friend bool operator==(const TaskKnowledge&, const TaskKnowledge&) = default;
};

}  // namespace apprentice
