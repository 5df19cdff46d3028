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

#include "search/search.h"
#include "world/action.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

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
  // What relevance pruning did (search/relevance.h).
  const std::vector<std::string>& notes() const { return notes_; }

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
  std::vector<std::string> notes_;
  std::chrono::steady_clock::time_point started_;
};

// Convenience: plans from the state to the goal with the given options.
PlanResult find_plan(const Domain& domain, const Universe& universe, const State& initial,
                     const Goal& goal, const SearchOptions& options);

}  // namespace apprentice
