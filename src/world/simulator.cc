#include "world/simulator.h"

namespace apprentice {

Simulator::Simulator(World world) : world_(std::move(world)) {}

Status Simulator::execute(const Action& action) {
  auto reason = why_not_applicable(*world_.domain, *world_.universe, world_.state, action);
  if (reason)
    return make_error(ErrorCode::kFailedPrecondition,
                      "cannot " + format_action(*world_.domain, *world_.universe, action) + ": " + *reason);
  world_.state = apply(*world_.domain, world_.state, action);
  history_.push_back(action);
  return {};
}

}  // namespace apprentice
