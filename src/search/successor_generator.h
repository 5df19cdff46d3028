// The operators applicable in a state, found through an index by
// precondition rather than by testing every operator.
//
// Each operator is *watched* by one of its positive preconditions: the one
// that fewest operators require, which in practice is the one least often
// true ((on ketchup1 table1) rather than (handempty)). Generating
// successors walks the true propositions of the state and tests only the
// operators they watch, plus the few with no positive precondition. Every
// operator is watched once, so none is reported twice.
#pragma once

#include <cstdint>
#include <vector>

#include "search/ground_task.h"

namespace apprentice {

class SuccessorGenerator {
 public:
  explicit SuccessorGenerator(const GroundTask& task);

  // Replaces the contents of `out` with the applicable operators, in a
  // deterministic order. Allocates only if `out` must grow.
  void applicable(const StateWord* state, std::vector<OperatorId>& out) const;

 private:
  const GroundTask& task_;
  std::vector<std::uint32_t> watch_begin_;  // by proposition, into watched_; one extra at the end
  std::vector<OperatorId> watched_;
  std::vector<OperatorId> unwatched_;  // operators without positive preconditions
};

}  // namespace apprentice
