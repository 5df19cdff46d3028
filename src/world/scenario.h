// A scenario file (YAML) holds a world and the task an instructor will
// teach in it. The format is documented in docs/scenarios.md.
//
// The agent is given only the World; the TaskStructure reaches it through
// the instructor's words, and the Intent is for the instructor and the
// metrics alone.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"
#include "world/vocabulary.h"

namespace apprentice {

// What the robot perceives: the action model, the objects and the state.
// A value: copies share the immutable domain and universe and copy the
// state, so each Simulator works on its own copy.
struct World {
  std::shared_ptr<const Domain> domain;
  Vocabulary vocabulary;
  std::shared_ptr<const Universe> universe;
  State state;
  std::string location;  // where the robot is: "kitchen"
};

struct Subtask {
  std::string verb;  // "clear"
  ObjectId place = 0;  // the surface or receptacle it empties: table1
};

struct TaskStructure {
  std::string name;  // "tidy kitchen"
  std::vector<Subtask> subtasks;
};

// What the instructor wants for objects of one category in one subtask.
struct IntentEntry {
  std::string subtask;   // "clear"
  std::string category;  // "ceramic-plate"
  ObjectId receptacle = 0;
  bool closed = false;   // the receptacle must end closed
};

struct Scenario {
  std::string name;
  std::filesystem::path source;       // the YAML file
  std::filesystem::path domain_path;  // resolved relative to the YAML file
  World world;                        // world.state is the initial state
  TaskStructure task;
  std::vector<IntentEntry> intent;

  const IntentEntry* find_intent(std::string_view subtask, std::string_view category) const;
  // The instructor's goal for one object: (in o r), plus (closed r) if wanted.
  std::optional<Goal> intended_goal(std::string_view subtask, ObjectId object) const;
  // The subtask whose place the object starts at, if any.
  const Subtask* subtask_of(ObjectId object) const;
  // All goal assertions the intent makes for this scenario's objects: one
  // placement per object to tidy plus one (closed r) per receptacle that
  // must end closed. Sorted, without duplicates.
  std::vector<Literal> goal_assertions() const;
};

// Loads and validates a scenario and its domain. Errors carry file:line and
// the code kInvalidInput (or kNotFound for a missing file); nothing partly
// loaded is ever returned.
Result<Scenario> load_scenario(const std::filesystem::path& path);

// The same from YAML text; `source` names it in messages and relative
// domain paths resolve against its directory.
Result<Scenario> parse_scenario(std::string_view yaml_text, const std::filesystem::path& source);

}  // namespace apprentice
