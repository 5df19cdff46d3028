#include "search/ff_heuristic.h"

#include <algorithm>
#include <bit>

namespace apprentice {

FfHeuristic::FfHeuristic(const GroundTask& task) : task_(task), propositions_(task.proposition_count()) {
  // "False" nodes for the facts some operator or the goal requires false.
  false_node_.assign(propositions_, kNone);
  auto need_false = [&](PropositionId p) {
    if (false_node_[p] != kNone) return;
    false_node_[p] = static_cast<std::uint32_t>(propositions_ + false_of_.size());
    false_of_.push_back(p);
  };
  for (OperatorId o = 0; o < task.operator_count(); ++o)
    for (PropositionId p : task.list(task.op(o).requires_false)) need_false(p);
  for (PropositionId p : task.goal_false()) need_false(p);
  const std::size_t nodes = propositions_ + false_of_.size();

  pre_begin_.push_back(0);
  effect_begin_.push_back(0);
  for (OperatorId o = 0; o < task.operator_count(); ++o) {
    const GroundOperator& op = task.op(o);
    for (PropositionId p : task.list(op.requires_true)) pre_.push_back(p);
    for (PropositionId p : task.list(op.requires_false)) pre_.push_back(false_node_[p]);
    for (PropositionId p : task.list(op.adds)) effect_.push_back(p);
    for (PropositionId p : task.list(op.deletes))
      if (false_node_[p] != kNone) effect_.push_back(false_node_[p]);
    pre_begin_.push_back(static_cast<std::uint32_t>(pre_.size()));
    effect_begin_.push_back(static_cast<std::uint32_t>(effect_.size()));
    if (pre_begin_[o] == pre_begin_[o + 1]) no_precondition_.push_back(o);
  }
  std::vector<std::uint32_t> count(nodes + 1, 0);
  for (Node n : pre_) ++count[n];
  required_by_begin_.assign(nodes + 1, 0);
  for (std::size_t n = 0; n < nodes; ++n) required_by_begin_[n + 1] = required_by_begin_[n] + count[n];
  required_by_.resize(pre_.size());
  std::vector<std::uint32_t> next(required_by_begin_.begin(), required_by_begin_.end() - 1);
  for (OperatorId o = 0; o < task.operator_count(); ++o)
    for (std::uint32_t k = pre_begin_[o]; k < pre_begin_[o + 1]; ++k) required_by_[next[pre_[k]]++] = o;

  for (PropositionId p : task.goal_true()) goal_.push_back(p);
  for (PropositionId p : task.goal_false()) goal_.push_back(false_node_[p]);
  std::sort(goal_.begin(), goal_.end());
  goal_.erase(std::unique(goal_.begin(), goal_.end()), goal_.end());

  cost_.assign(nodes, -1);
  supporter_.assign(nodes, kNone);
  unmet_.assign(task.operator_count(), 0);
  op_cost_.assign(task.operator_count(), 0);
  marked_node_.assign(nodes, 0);
  marked_op_.assign(task.operator_count(), 0);
}

void FfHeuristic::push(Node node, int cost) {
  const auto c = static_cast<std::size_t>(cost);
  if (c >= buckets_.size()) buckets_.resize(c + 1);
  buckets_[c].push_back(node);
}

int FfHeuristic::explore(const StateWord* state) {
  std::fill(cost_.begin(), cost_.end(), -1);
  for (OperatorId o = 0; o < unmet_.size(); ++o) {
    unmet_[o] = pre_begin_[o + 1] - pre_begin_[o];
    op_cost_[o] = 1;
  }
  for (std::size_t w = 0; w < task_.words(); ++w) {
    for (StateWord bits = state[w]; bits != 0; bits &= bits - 1) {
      const auto p = static_cast<Node>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
      cost_[p] = 0;
      supporter_[p] = kNone;
      push(p, 0);
    }
  }
  for (std::size_t k = 0; k < false_of_.size(); ++k) {
    if (test_bit(state, false_of_[k])) continue;
    const auto n = static_cast<Node>(propositions_ + k);
    cost_[n] = 0;
    supporter_[n] = kNone;
    push(n, 0);
  }
  auto fire = [&](OperatorId o) {
    const int c = op_cost_[o];
    for (std::uint32_t k = effect_begin_[o]; k < effect_begin_[o + 1]; ++k) {
      const Node e = effect_[k];
      if (cost_[e] != -1 && cost_[e] <= c) continue;
      cost_[e] = c;
      supporter_[e] = o;
      push(e, c);
    }
  };
  for (OperatorId o : no_precondition_) fire(o);

  // Nodes leave the buckets in order of cost, so each node's cost is final
  // when it leaves; exploration stops once every goal node has left.
  std::size_t goals_left = 0;
  for (Node g : goal_) marked_node_[g] = 2, ++goals_left;  // 2: a goal not yet final
  std::size_t c = 0;
  for (; c < buckets_.size() && goals_left > 0; ++c) {
    // push() may grow buckets_, so index rather than hold a reference.
    for (std::size_t i = 0; i < buckets_[c].size() && goals_left > 0; ++i) {
      const Node n = buckets_[c][i];
      if (cost_[n] != static_cast<int>(c)) continue;  // a stale, costlier entry
      if (marked_node_[n] == 2) marked_node_[n] = 0, --goals_left;
      for (std::uint32_t k = required_by_begin_[n]; k < required_by_begin_[n + 1]; ++k) {
        const OperatorId o = required_by_[k];
        op_cost_[o] += static_cast<int>(c);
        if (--unmet_[o] == 0) fire(o);
      }
    }
  }
  for (auto& bucket : buckets_) bucket.clear();
  int sum = 0;
  for (Node g : goal_) marked_node_[g] = 0;
  for (Node g : goal_) {
    if (cost_[g] < 0) return kDeadEnd;
    sum += cost_[g];
  }
  return sum;
}

int FfHeuristic::extract(std::vector<OperatorId>* preferred) {
  stack_.assign(goal_.begin(), goal_.end());
  touched_ops_.clear();
  while (!stack_.empty()) {
    const Node n = stack_.back();
    stack_.pop_back();
    if (marked_node_[n]) continue;
    marked_node_[n] = 1;
    const std::uint32_t o = supporter_[n];
    if (cost_[n] == 0 || marked_op_[o]) continue;
    marked_op_[o] = 1;
    touched_ops_.push_back(o);
    for (std::uint32_t k = pre_begin_[o]; k < pre_begin_[o + 1]; ++k) stack_.push_back(pre_[k]);
  }
  if (preferred) preferred->clear();
  for (OperatorId o : touched_ops_) {
    marked_op_[o] = 0;
    if (!preferred) continue;
    bool applicable = true;
    for (std::uint32_t k = pre_begin_[o]; k < pre_begin_[o + 1]; ++k)
      if (cost_[pre_[k]] != 0) applicable = false;
    if (applicable) preferred->push_back(o);
  }
  if (preferred) std::sort(preferred->begin(), preferred->end());
  std::fill(marked_node_.begin(), marked_node_.end(), 0);
  return static_cast<int>(touched_ops_.size());
}

int FfHeuristic::evaluate(const StateWord* state, std::vector<OperatorId>* preferred) {
  if (explore(state) == kDeadEnd) {
    if (preferred) preferred->clear();
    return kDeadEnd;
  }
  return extract(preferred);
}

}  // namespace apprentice
