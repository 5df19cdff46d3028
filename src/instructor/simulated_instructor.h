// The simulated instructor of the experiments. It knows the scenario's
// intent and speaks exactly as the STARS tidy-kitchen instructor script
// does: the task structure, one goal description per kind of object,
// next-step commands from a shortest plan, and yes or no to proposals.
#pragma once

#include <string>

#include "instructor/instructor.h"
#include "world/scenario.h"

namespace apprentice {

class SimulatedInstructor final : public Instructor {
 public:
  explicit SimulatedInstructor(Scenario scenario);

  Result<std::string> answer(const Question& question, const World& world) override;

 private:
  // Where the instructor is in teaching the task structure: for each
  // subtask in turn, announce the loop, then the subtask, then (once the
  // agent has done the subtask once) "Repeat.", then move to the next.
  enum class Phase { kAnnounceLoop, kAnnounceSubtask, kRepeat, kNextSubtask };

  std::string next_task_step(const World& now);
  // "Which ...?": the look-alike it means, by its properties.
  std::string which(const Question& question, const World& world) const;
  std::string goal_or_done(const Question& question, const World& world) const;
  std::string next_action(const Question& question, const World& world) const;
  bool accepts_goal(const Question& question, const World& world) const;
  bool accepts_action(const Question& question, const World& world) const;
  // The instructor's goal for the object in the question's subtask.
  std::optional<Goal> wanted_goal(const Question& question, const World& world) const;

  Scenario scenario_;
  std::size_t subtask_index_ = 0;
  Phase phase_ = Phase::kAnnounceLoop;
};

// The length of a shortest plan from `state` to `goal`, or nullopt if none
// exists within `max_depth` steps.
std::optional<int> shortest_plan_length(const World& world, const State& state, const Goal& goal,
                                        int max_depth);

}  // namespace apprentice
