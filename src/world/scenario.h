// A scenario file (YAML) holds a world and the task an instructor will
// teach in it. The format is documented in docs/scenarios.md.
//
// The agent is given only the World (world/world.h); the TaskStructure
// reaches it through the instructor's words, and the Intent is for the
// instructor and the metrics alone. Nothing of the agent includes this
// header (scripts/check-layers.py).
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
#include "world/world.h"

namespace apprentice {

struct Subtask {
  std::string verb;  // "clear"
  // The surfaces or receptacles it empties, in id order: one place
  // (`place: table1`), or every place of one category (`place: bag`: bag1,
  // bag2, bag3). Never empty; several places always share a category.
  std::vector<ObjectId> places;

  bool covers(ObjectId place) const;
};

// Empty (no name, no subtasks) when the file has no `task`.
struct TaskStructure {
  std::string name;  // "tidy kitchen"
  std::vector<Subtask> subtasks;
};

// What the instructor wants for objects of one category in one subtask.
struct IntentEntry {
  std::string subtask;   // "clear"
  // Which subtask, as an index into TaskStructure::subtasks: a verb may be
  // given to several subtasks with other places ("clear" the floor, then
  // "clear" the counter), and the entry's `from` says which.
  std::size_t subtask_index = 0;
  std::string category;  // "ceramic-plate"
  // Where such objects go: a receptacle gives (in o p), a surface (on o p).
  ObjectId place = 0;
  bool closed = false;   // the place (a receptacle with a door) must end closed
};

struct Scenario {
  std::string name;
  std::filesystem::path source;       // the YAML file
  std::filesystem::path domain_path;  // resolved relative to the YAML file
  World world;                        // world.state is the initial state
  TaskStructure task;                 // empty without `task`
  std::vector<IntentEntry> intent;
  // Whether the file has an `intent` (possibly empty). Without one the
  // person teaching is the only authority on the goals: there is nothing to
  // measure completion against, and no simulated instructor.
  bool has_intent = false;
  // The published figures this scenario reproduces: "table3" for the
  // paper's kitchen (Kirk et al., Table 3); empty for any other scenario.
  std::string reference;

  // The first entry for the verb and category (the one, when the verb names
  // one subtask).
  const IntentEntry* find_intent(std::string_view subtask, std::string_view category) const;
  // The entry for one object in the subtask `subtask` (a verb): where
  // several subtasks share the verb, the one at whose places the object
  // starts; else as find_intent.
  const IntentEntry* intent_for(std::string_view subtask, ObjectId object) const;
  // The instructor's goal for one object: (in o p) for a receptacle or
  // (on o p) for a surface, plus (closed p) if wanted.
  std::optional<Goal> intended_goal(std::string_view subtask, ObjectId object) const;
  // The subtask at one of whose places the object starts, if any.
  const Subtask* subtask_of(ObjectId object) const;
  // The objects the intent is about: every item that starts at a subtask's
  // place (each has an intent entry), in id order.
  std::vector<ObjectId> objects_to_tidy() const;
  // All goal assertions the intent makes for this scenario's objects: one
  // placement per object to tidy plus one (closed r) per receptacle that
  // must end closed. Sorted, without duplicates.
  std::vector<Literal> goal_assertions() const;
};

// Loads and validates a scenario and its domain. Errors carry file:line and
// the code kInvalidInput (or kNotFound for a missing file); nothing partly
// loaded is ever returned. The domain is a file relative to the scenario;
// a bare name ("domain: kitchen") that names no file there is looked for as
// NAME.pddl in `domain_folders` (the shipped domains: the face's
// load_world passes data_dir()/domains).
Result<Scenario> load_scenario(const std::filesystem::path& path,
                               const std::vector<std::filesystem::path>& domain_folders = {});

// The same from YAML text; `source` names it in messages and relative
// domain paths resolve against its directory.
Result<Scenario> parse_scenario(std::string_view yaml_text, const std::filesystem::path& source,
                                const std::vector<std::filesystem::path>& domain_folders = {});

}  // namespace apprentice
