// The simulated world. It holds the true state and changes it only through
// executed actions, checking each action's preconditions the way a robot's
// controller would refuse an impossible command.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "util/result.h"
#include "world/action.h"
#include "world/world.h"

namespace apprentice {

class Simulator {
 public:
  explicit Simulator(World world);

  // What the robot perceives now.
  const World& world() const { return world_; }
  const State& state() const { return world_.state; }

  // Executes the action, or returns kFailedPrecondition saying which
  // precondition failed; the state is unchanged then.
  Status execute(const Action& action);

  // Every action executed so far, in order.
  const std::vector<Action>& history() const { return history_; }

 private:
  World world_;
  std::vector<Action> history_;
};

}  // namespace apprentice
