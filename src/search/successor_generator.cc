#include "search/successor_generator.h"

#include <bit>

namespace apprentice {

SuccessorGenerator::SuccessorGenerator(const GroundTask& task) : task_(task) {
  const std::size_t n = task.proposition_count();
  std::vector<std::uint32_t> required_by(n, 0);
  for (OperatorId o = 0; o < task.operator_count(); ++o)
    for (PropositionId p : task.list(task.op(o).requires_true)) ++required_by[p];
  std::vector<PropositionId> watch(task.operator_count(), 0);
  std::vector<std::uint32_t> count(n + 1, 0);
  for (OperatorId o = 0; o < task.operator_count(); ++o) {
    auto pre = task.list(task.op(o).requires_true);
    if (pre.empty()) {
      unwatched_.push_back(o);
      continue;
    }
    PropositionId best = pre[0];
    for (PropositionId p : pre)
      if (required_by[p] < required_by[best]) best = p;
    watch[o] = best;
    ++count[best];
  }
  watch_begin_.assign(n + 1, 0);
  for (std::size_t p = 0; p < n; ++p) watch_begin_[p + 1] = watch_begin_[p] + count[p];
  watched_.resize(watch_begin_[n]);
  std::vector<std::uint32_t> next(watch_begin_.begin(), watch_begin_.end() - 1);
  for (OperatorId o = 0; o < task.operator_count(); ++o)
    if (!task.list(task.op(o).requires_true).empty()) watched_[next[watch[o]]++] = o;
}

void SuccessorGenerator::applicable(const StateWord* state, std::vector<OperatorId>& out) const {
  out.clear();
  for (OperatorId o : unwatched_)
    if (task_.applicable(state, o)) out.push_back(o);
  const std::size_t words = task_.words();
  for (std::size_t w = 0; w < words; ++w) {
    for (StateWord bits = state[w]; bits != 0; bits &= bits - 1) {
      const auto p = static_cast<PropositionId>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
      for (std::uint32_t k = watch_begin_[p]; k < watch_begin_[p + 1]; ++k)
        if (task_.applicable(state, watched_[k])) out.push_back(watched_[k]);
    }
  }
}

}  // namespace apprentice
