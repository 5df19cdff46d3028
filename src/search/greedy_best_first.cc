#include "search/greedy_best_first.h"

#include <algorithm>

#include "search/relevance.h"

namespace apprentice {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The budgets and the progress callback read the clock only every this
// many states, which keeps the clock out of the hot path.
constexpr std::uint64_t kStatesPerClockCheck = 64;
constexpr int kPreferredBoost = 1000;

}  // namespace

void GreedyBestFirstSearch::BucketQueue::push(int key, Edge edge) {
  const auto k = static_cast<std::size_t>(key);
  if (k >= buckets_.size()) {
    buckets_.resize(k + 1);
    heads_.resize(k + 1, 0);
  }
  buckets_[k].push_back(edge);
  if (size_ == 0 || k < lowest_) lowest_ = k;
  ++size_;
}

GreedyBestFirstSearch::Edge GreedyBestFirstSearch::BucketQueue::pop() {
  while (heads_[lowest_] == buckets_[lowest_].size()) ++lowest_;
  std::vector<Edge>& bucket = buckets_[lowest_];
  const Edge edge = bucket[heads_[lowest_]++];
  if (heads_[lowest_] == bucket.size()) {
    bucket.clear();  // keeps its capacity for later edges
    heads_[lowest_] = 0;
  }
  --size_;
  return edge;
}

GreedyBestFirstSearch::GreedyBestFirstSearch(const Domain& domain, const Universe& universe, const State& initial,
                                             const Goal& goal, SearchOptions options)
    : options_(std::move(options)), started_(Clock::now()), next_report_(started_ + options_.progress_interval) {
  SearchScope scope = search_scope(domain, universe, initial, goal, options_.prune_irrelevant);
  notes_ = std::move(scope.notes);
  task_ = std::make_unique<GroundTask>(domain, universe, scope.objects, scope.state, goal);
  successors_ = std::make_unique<SuccessorGenerator>(*task_);
  heuristic_ = std::make_unique<FfHeuristic>(*task_);
  registry_ = std::make_unique<StateRegistry>(task_->words());
  preferred_mark_.assign(task_->operator_count(), 0);
  scratch_.assign(task_->words(), 0);
  statistics_.relevant_objects = scope.objects.size();
  statistics_.ground_actions = task_->operator_count();
  statistics_.propositions = task_->proposition_count();
  statistics_.grounding_ms = ms_since(started_);

  if (task_->goal_statically_false()) {
    finish(SearchStatus::kExhausted);
    return;
  }
  const StateId root = registry_->insert(task_->initial().data()).first;
  parent_.push_back(kNoState);
  via_.push_back(0);
  if (task_->is_goal(registry_->get(root))) {
    solved(root);
    return;
  }
  expand(root, registry_->get(root));
  if (open_[0].empty()) finish(SearchStatus::kExhausted);
}

void GreedyBestFirstSearch::expand(StateId id, const StateWord* state) {
  ++statistics_.nodes_expanded;
  ++statistics_.nodes_evaluated;
  const int h = heuristic_->evaluate(state, &preferred_);
  if (statistics_.nodes_evaluated == 1) statistics_.initial_heuristic = h;
  if (h == FfHeuristic::kDeadEnd) {
    ++statistics_.dead_ends;
    return;
  }
  if (statistics_.best_heuristic < 0 || h < statistics_.best_heuristic) {
    // Progress: the preferred edges get the next turns.
    if (statistics_.best_heuristic >= 0) priority_[1] -= kPreferredBoost;
    statistics_.best_heuristic = h;
  }
  successors_->applicable(state, applicable_);
  const std::uint64_t stamp = statistics_.nodes_expanded;
  for (OperatorId o : preferred_) preferred_mark_[o] = stamp;
  for (OperatorId o : applicable_) {
    open_[0].push(h, Edge{id, o});
    if (preferred_mark_[o] == stamp) open_[1].push(h, Edge{id, o});
  }
  statistics_.nodes_generated += applicable_.size();
}

bool GreedyBestFirstSearch::pop(Edge& edge) {
  if (open_[0].empty() && open_[1].empty()) return false;
  const int list = open_[1].empty() || (!open_[0].empty() && priority_[0] <= priority_[1]) ? 0 : 1;
  ++priority_[list];
  edge = open_[list].pop();
  return true;
}

bool GreedyBestFirstSearch::budget_spent() {
  if (options_.max_nodes && statistics_.nodes_expanded >= *options_.max_nodes) return true;
  if (!options_.max_time && !options_.progress) return false;
  if (steps_since_clock_++ % kStatesPerClockCheck != 0) return false;
  const Clock::time_point now = Clock::now();
  if (options_.max_time && now - started_ >= *options_.max_time) return true;
  if (options_.progress && now >= next_report_) {
    report_progress();
    next_report_ = now + options_.progress_interval;
  }
  return false;
}

void GreedyBestFirstSearch::report_progress() {
  SearchProgress progress;
  progress.nodes_expanded = statistics_.nodes_expanded;
  progress.elapsed_ms = ms_since(started_);
  progress.nodes_per_second =
      progress.elapsed_ms > 0 ? static_cast<double>(progress.nodes_expanded) * 1000.0 / progress.elapsed_ms : 0;
  progress.best_heuristic = statistics_.best_heuristic;
  options_.progress(progress);
}

SearchStatus GreedyBestFirstSearch::step(std::uint64_t node_budget) {
  std::uint64_t taken = 0;
  while (status_ == SearchStatus::kInProgress && taken < node_budget) {
    if (budget_spent()) {
      finish(SearchStatus::kBudgetExhausted);
      break;
    }
    Edge edge;
    if (!pop(edge)) {
      finish(SearchStatus::kExhausted);
      break;
    }
    task_->apply(registry_->get(edge.parent), edge.op, scratch_.data());
    const auto [id, fresh] = registry_->insert(scratch_.data());
    if (!fresh) continue;
    parent_.push_back(edge.parent);
    via_.push_back(edge.op);
    if (task_->is_goal(scratch_.data())) {
      solved(id);
      break;
    }
    expand(id, scratch_.data());
    ++taken;
  }
  if (status_ == SearchStatus::kInProgress) statistics_.elapsed_ms = ms_since(started_);
  return status_;
}

SearchStatus GreedyBestFirstSearch::run() {
  while (step(1 << 16) == SearchStatus::kInProgress) {
  }
  return status_;
}

void GreedyBestFirstSearch::solved(StateId goal) {
  std::vector<OperatorId> ops;
  for (StateId s = goal; parent_[s] != kNoState; s = parent_[s]) ops.push_back(via_[s]);
  std::reverse(ops.begin(), ops.end());
  if (options_.improve_plan) {
    const std::size_t before = ops.size();
    ops = shortened(std::move(ops));
    statistics_.steps_removed = before - ops.size();
  }
  plan_.clear();
  for (OperatorId o : ops) plan_.push_back(task_->op(o).action);
  finish(SearchStatus::kSolved);
}

std::vector<OperatorId> GreedyBestFirstSearch::shortened(std::vector<OperatorId> ops) const {
  const std::size_t words = task_->words();
  std::vector<StateWord> prefix(task_->initial()), trial(words), next(words);
  std::vector<OperatorId> kept;
  for (bool changed = true; changed;) {
    changed = false;
    prefix = task_->initial();
    for (std::size_t i = 0; i < ops.size();) {
      // Drop ops[i] and every later action that is then inapplicable.
      trial = prefix;
      kept.assign(ops.begin(), ops.begin() + static_cast<std::ptrdiff_t>(i));
      for (std::size_t j = i + 1; j < ops.size(); ++j) {
        if (!task_->applicable(trial.data(), ops[j])) continue;
        task_->apply(trial.data(), ops[j], next.data());
        trial.swap(next);
        kept.push_back(ops[j]);
      }
      if (task_->is_goal(trial.data())) {
        ops.swap(kept);
        changed = true;
        continue;  // try the action now at position i
      }
      task_->apply(prefix.data(), ops[i], next.data());
      prefix.swap(next);
      ++i;
    }
  }
  return ops;
}

void GreedyBestFirstSearch::finish(SearchStatus status) {
  status_ = status;
  statistics_.states_registered = registry_ ? registry_->size() : 0;
  statistics_.elapsed_ms = ms_since(started_);
}

PlanResult find_greedy_plan(const Domain& domain, const Universe& universe, const State& initial, const Goal& goal,
                            const SearchOptions& options) {
  GreedyBestFirstSearch search(domain, universe, initial, goal, options);
  search.run();
  return PlanResult{search.status(), search.plan(), search.statistics(), search.notes()};
}

}  // namespace apprentice
