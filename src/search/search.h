// What every planner of this module shares: its outcome (a status, never
// an exception), its options and budgets, its statistics, and progress
// reports for long searches.
//
// Two planners use them: IterativeDeepeningSearch (search/iterative_deepening.h),
// which finds shortest plans up to a depth limit, as the paper's agent
// does; and GreedyBestFirstSearch (search/greedy_best_first.h), which plans
// whole tasks with no depth limit.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "world/action.h"

namespace apprentice {

enum class SearchStatus {
  kInProgress,       // step() may be called again
  kSolved,           // plan() is a plan (for iterative deepening, a shortest one)
  kExhausted,        // no plan exists (for iterative deepening: none of length <= max_depth)
  kBudgetExhausted,  // the node or time budget ran out first
};

const char* to_string(SearchStatus status);

// Reported about once a second while a search runs (see SearchOptions::progress).
struct SearchProgress {
  std::uint64_t nodes_expanded = 0;
  double elapsed_ms = 0;
  double nodes_per_second = 0;
  int best_heuristic = -1;  // the lowest heuristic value seen so far; -1 if none
};

struct SearchOptions {
  int max_depth = 4;  // iterative deepening only
  // Unlimited when unset.
  std::optional<std::uint64_t> max_nodes;
  std::optional<std::chrono::milliseconds> max_time;
  // See search/relevance.h for when pruning is safe; the analysis turns it
  // off by itself where it is not.
  bool prune_irrelevant = true;
  // Greedy best-first search only: shorten the plan found by removing
  // actions that turn out not to be needed (see greedy_best_first.h).
  bool improve_plan = true;
  // Greedy best-first search only: called with the search's progress once
  // progress_interval has passed, and then about every progress_interval.
  // Empty: never called.
  std::function<void(const SearchProgress&)> progress;
  std::chrono::milliseconds progress_interval{1000};
};

struct SearchStatistics {
  std::uint64_t nodes_expanded = 0;   // states whose successors were generated
  std::uint64_t nodes_generated = 0;  // successor states (or, lazily, edges) created
  int depth_limit_reached = 0;        // iterative deepening: the last depth limit tried
  std::size_t relevant_objects = 0;
  std::size_t ground_actions = 0;
  double elapsed_ms = 0;
  // Greedy best-first search only.
  std::uint64_t nodes_evaluated = 0;  // states whose heuristic value was computed
  std::uint64_t dead_ends = 0;        // evaluated states from which no relaxed plan exists
  std::size_t states_registered = 0;  // distinct states seen
  std::size_t propositions = 0;       // dynamic facts of the ground task
  int initial_heuristic = -1;         // FF value of the initial state; -1 for a dead end
  int best_heuristic = -1;            // the lowest FF value reached
  std::size_t steps_removed = 0;      // by plan improvement
  double grounding_ms = 0;            // relevance analysis and grounding, part of elapsed_ms
};

struct PlanResult {
  SearchStatus status = SearchStatus::kExhausted;
  std::vector<Action> plan;
  SearchStatistics statistics;
  // What relevance pruning did and why it is safe, or why it was off:
  // sentences for --verbose.
  std::vector<std::string> notes;
};

}  // namespace apprentice
