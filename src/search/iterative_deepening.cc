#include "search/iterative_deepening.h"

#include <algorithm>

#include "search/relevance.h"

namespace apprentice {

const char* to_string(SearchStatus status) {
  switch (status) {
    case SearchStatus::kInProgress: return "in-progress";
    case SearchStatus::kSolved: return "solved";
    case SearchStatus::kExhausted: return "exhausted";
    case SearchStatus::kBudgetExhausted: return "budget-exhausted";
  }
  return "unknown";
}

IterativeDeepeningSearch::IterativeDeepeningSearch(const Domain& domain, const Universe& universe,
                                                   const State& initial, Goal goal,
                                                   SearchOptions options)
    : domain_(domain), goal_(std::move(goal)), options_(options),
      started_(std::chrono::steady_clock::now()) {
  SearchScope scope = search_scope(domain, universe, initial, goal_, options_.prune_irrelevant);
  initial_ = std::move(scope.state);
  notes_ = std::move(scope.notes);
  const std::vector<ObjectId>& objects = scope.objects;
  actions_ = ground_actions(domain, universe, objects, initial_);
  statistics_.relevant_objects = objects.size();
  statistics_.ground_actions = actions_.size();
  if (goal_.satisfied_by(initial_)) {
    finish(SearchStatus::kSolved);
    return;
  }
  if (options_.max_depth <= 0) {
    finish(SearchStatus::kExhausted);
    return;
  }
  depth_limit_ = 1;
  start_iteration();
}

void IterativeDeepeningSearch::start_iteration() {
  stack_.clear();
  stack_.push_back(Frame{initial_, 0, std::nullopt});
  deeper_exists_ = false;
  statistics_.depth_limit_reached = depth_limit_;
}

void IterativeDeepeningSearch::finish(SearchStatus status) {
  status_ = status;
  stack_.clear();
  auto elapsed = std::chrono::steady_clock::now() - started_;
  statistics_.elapsed_ms = std::chrono::duration<double, std::milli>(elapsed).count();
}

bool IterativeDeepeningSearch::on_path(const State& state) const {
  return std::any_of(stack_.begin(), stack_.end(), [&](const Frame& f) { return f.state == state; });
}

bool IterativeDeepeningSearch::budget_spent() const {
  if (options_.max_nodes && statistics_.nodes_expanded >= *options_.max_nodes) return true;
  if (options_.max_time && std::chrono::steady_clock::now() - started_ >= *options_.max_time) return true;
  return false;
}

SearchStatus IterativeDeepeningSearch::step(std::uint64_t node_budget) {
  std::uint64_t expanded_here = 0;
  while (status_ == SearchStatus::kInProgress) {
    if (stack_.empty()) {
      // This depth limit is done without a plan.
      if (!deeper_exists_ || depth_limit_ >= options_.max_depth) {
        finish(SearchStatus::kExhausted);
        break;
      }
      ++depth_limit_;
      start_iteration();
      continue;
    }
    Frame& top = stack_.back();
    int depth = static_cast<int>(stack_.size()) - 1;
    if (depth >= depth_limit_) {
      deeper_exists_ = true;
      stack_.pop_back();
      continue;
    }
    if (top.next_action == 0) {
      if (expanded_here >= node_budget) break;
      if (budget_spent()) {
        finish(SearchStatus::kBudgetExhausted);
        break;
      }
      ++statistics_.nodes_expanded;
      ++expanded_here;
    }
    bool pushed = false;
    while (top.next_action < actions_.size()) {
      const Action& action = actions_[top.next_action++];
      if (!is_applicable(domain_, top.state, action)) continue;
      State next = apply(domain_, top.state, action);
      ++statistics_.nodes_generated;
      if (on_path(next)) continue;
      if (goal_.satisfied_by(next)) {
        plan_.clear();
        for (std::size_t i = 1; i < stack_.size(); ++i) plan_.push_back(*stack_[i].via);
        plan_.push_back(action);
        finish(SearchStatus::kSolved);
        return status_;
      }
      stack_.push_back(Frame{std::move(next), 0, action});
      pushed = true;
      break;
    }
    if (!pushed && status_ == SearchStatus::kInProgress) stack_.pop_back();
  }
  if (status_ != SearchStatus::kInProgress) return status_;
  statistics_.elapsed_ms = std::chrono::duration<double, std::milli>(
                               std::chrono::steady_clock::now() - started_).count();
  return status_;
}

SearchStatus IterativeDeepeningSearch::run() {
  while (step(1 << 16) == SearchStatus::kInProgress) {
  }
  return status_;
}

PlanResult find_plan(const Domain& domain, const Universe& universe, const State& initial,
                     const Goal& goal, const SearchOptions& options) {
  IterativeDeepeningSearch search(domain, universe, initial, goal, options);
  search.run();
  return PlanResult{search.status(), search.plan(), search.statistics(), search.notes()};
}

}  // namespace apprentice
