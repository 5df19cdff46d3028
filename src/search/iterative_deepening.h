// Iterative-deepening depth-first search over ground actions: the agent's
// own planner, as in the paper. It returns a shortest plan within the depth
// limit, or reports that none exists ("exhausted"), which is an outcome,
// not an error.
//
// It is a stepper: step(n) expands at most n more nodes and returns, so a
// caller can interleave it with other work and stop it on a node or time
// budget. It is deterministic: the same problem gives the same plan and the
// same statistics (apart from elapsed time).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "world/action.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

enum class SearchStatus {
  kInProgress,       // step() may be called again
  kSolved,           // plan() is a shortest plan
  kExhausted,        // no plan of length <= max_depth exists
  kBudgetExhausted,  // the node or time budget ran out first
};

const char* to_string(SearchStatus status);

struct SearchOptions {
  int max_depth = 4;
  // Unlimited when unset.
  std::optional<std::uint64_t> max_nodes;
  std::optional<std::chrono::milliseconds> max_time;
  // See search/relevance.h for when turning this off is needed.
  bool prune_irrelevant = true;
};

struct SearchStatistics {
  std::uint64_t nodes_expanded = 0;   // states whose successors were generated
  std::uint64_t nodes_generated = 0;  // successor states created
  int depth_limit_reached = 0;        // the last depth limit tried
  std::size_t relevant_objects = 0;
  std::size_t ground_actions = 0;
  double elapsed_ms = 0;
};

class IterativeDeepeningSearch {
 public:
  // Keeps references to domain and universe: they must outlive the search.
  IterativeDeepeningSearch(const Domain& domain, const Universe& universe, const State& initial,
                           Goal goal, SearchOptions options);

  // Expands up to `node_budget` nodes. Once it returns a final status, later
  // calls return the same status and do nothing.
  SearchStatus step(std::uint64_t node_budget);
  // Steps until a final status.
  SearchStatus run();

  SearchStatus status() const { return status_; }
  // The plan; valid once status() is kSolved.
  const std::vector<Action>& plan() const { return plan_; }
  const SearchStatistics& statistics() const { return statistics_; }

 private:
  struct Frame {
    State state;
    std::size_t next_action = 0;
    std::optional<Action> via;  // the action that led here; none at the root
  };

  bool on_path(const State& state) const;
  bool budget_spent() const;
  void start_iteration();
  void finish(SearchStatus status);

  const Domain& domain_;
  Goal goal_;
  SearchOptions options_;
  State initial_;
  std::vector<Action> actions_;
  std::vector<Frame> stack_;
  int depth_limit_ = 0;
  bool deeper_exists_ = false;  // some node was cut off by the depth limit
  SearchStatus status_ = SearchStatus::kInProgress;
  std::vector<Action> plan_;
  SearchStatistics statistics_;
  std::chrono::steady_clock::time_point started_;
};

// Convenience: plans from the state to the goal with the given options.
struct PlanResult {
  SearchStatus status = SearchStatus::kExhausted;
  std::vector<Action> plan;
  SearchStatistics statistics;
};
PlanResult find_plan(const Domain& domain, const Universe& universe, const State& initial,
                     const Goal& goal, const SearchOptions& options);

}  // namespace apprentice
