// What one run of the agent (learn or perform) did: per object, and in
// all. A plain value, with no part of the agent in it, so that the public
// face (face/apprentice.h) can hand it out.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace apprentice {

// Where an object's goal came from.
enum class GoalSource {
  kNone,         // no goal
  kMemory,       // learned before, for this kind in this subtask
  kInstructor,   // the teacher said it
  kLlm,          // the language model's goal, adopted
  kAnalogy,      // another kind's goal, taken by analogy
  kLikeness,     // decided from things like it
  kRule,         // decided by a rule induced from the goals
  kPersonRule,   // decided by a rule the person said
  kFleet,        // decided from other robots' knowledge
  kDecision,     // decided with no source ahead of the others
};

// The name in reports and JSON: "", "memory", "instructor", "llm",
// "analogy", "likeness", "rule", "person's rule", "fleet", "decision".
std::string_view to_string(GoalSource source);

// How one object went.
struct ObjectReport {
  std::string object;
  std::string subtask;
  // The category of the place whose part it was dealt with in ("floor" for
  // "clear the floor"): with `subtask`, the part its goal was learned or
  // corrected under. "" when it was dealt with in no part.
  std::string part_place;
  GoalSource goal_source = GoalSource::kNone;
  std::string goal;         // as PDDL, if any
  bool achieved = false;
  std::string note;         // why not, if not
  // For a thing no goal was known for: the place its sources believed it
  // goes to most (the place's name in the world) and that belief, 0..1,
  // before the teacher said anything; "" and 0 when nothing was proposed.
  // What calibration reads.
  std::string proposed;
  double belief = 0;
  // For a goal the agent decided (or the teacher confirmed), its evidence
  // as said then ("with trash, as you said", "like the mug"); "" else. What
  // "why did you put it there?" says once the goal has changed.
  std::string because;
};

struct AgentReport {
  std::vector<ObjectReport> objects;
  std::uint64_t search_nodes = 0;
  int searches = 0;
  int actions_executed = 0;
  int rule_actions = 0;     // actions chosen by learned rules
  int goals_learned = 0;
  int rules_learned = 0;
  // Where the agent would have needed help it could not get (for `run`).
  std::vector<std::string> help_needed;
  // What the agent carried over from other worlds (transfer.h), one line
  // each: the categories it took for learned ones, and the goals it
  // adopted by analogy.
  std::vector<std::string> renamed;
  std::vector<std::string> analogies;
  // What other robots learned while this one ran, as it said it ("Another
  // robot just learned where the ketchup goes.").
  std::vector<std::string> news;
  bool task_finished = false;  // the instructor said the task was done
};

}  // namespace apprentice
