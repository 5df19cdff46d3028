// The FF heuristic (Hoffmann and Nebel 2001): the length of a relaxed plan,
// one that ignores delete effects, extracted from the best supporters of
// the additive heuristic, with unit action costs. It also names the
// *preferred operators*: the relaxed plan's operators that are applicable
// in the state, which are the likeliest first steps.
//
// Negative preconditions and negative goals are not simply ignored, which
// would make the heuristic blind to opening a closed door before putting
// something in: each fact that is ever required false gets a second,
// "false" proposition, true in a state when the fact is not, and added by
// every operator that deletes the fact.
//
// Evaluation allocates nothing once the buffers have reached their size.
#pragma once

#include <cstdint>
#include <vector>

#include "search/ground_task.h"

namespace apprentice {

class FfHeuristic {
 public:
  static constexpr int kDeadEnd = -1;

  explicit FfHeuristic(const GroundTask& task);

  // The heuristic value of the state, or kDeadEnd if the relaxed goal is
  // unreachable (then no plan exists from it). If `preferred` is given, it
  // is replaced by the preferred operators, in increasing id order.
  int evaluate(const StateWord* state, std::vector<OperatorId>* preferred);

 private:
  using Node = std::uint32_t;  // a proposition or a "false" proposition
  static constexpr std::uint32_t kNone = 0xffffffffu;

  void push(Node node, int cost);
  int explore(const StateWord* state);  // additive costs; returns the goal's sum or kDeadEnd
  int extract(std::vector<OperatorId>* preferred);

  const GroundTask& task_;
  std::size_t propositions_ = 0;
  std::vector<std::uint32_t> false_node_;  // proposition -> its "false" node, or kNone
  std::vector<PropositionId> false_of_;    // "false" node - propositions_ -> proposition
  // Relaxed operators, in compressed rows.
  std::vector<std::uint32_t> pre_begin_, effect_begin_;  // per operator, one extra at the end
  std::vector<Node> pre_, effect_;
  std::vector<std::uint32_t> required_by_begin_;  // per node, one extra at the end
  std::vector<OperatorId> required_by_;
  std::vector<OperatorId> no_precondition_;
  std::vector<Node> goal_;

  // Per evaluation.
  std::vector<int> cost_;                 // per node; -1 unreached
  std::vector<std::uint32_t> supporter_;  // per node; kNone for true in the state
  std::vector<std::uint32_t> unmet_;      // per operator
  std::vector<int> op_cost_;              // per operator: 1 + sum of its preconditions' costs
  std::vector<std::vector<Node>> buckets_;  // the open nodes by cost
  std::vector<std::uint8_t> marked_node_, marked_op_;
  std::vector<Node> stack_;
  std::vector<OperatorId> touched_ops_;
};

}  // namespace apprentice
