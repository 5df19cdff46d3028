// Greedy best-first search with the FF heuristic: the planner for whole
// tasks, with no depth limit. It is the lazy variant with preferred
// operators that LAMA's first iteration uses (Richter and Westphal 2010):
//
// - Lazy evaluation: a successor is not evaluated when it is generated.
//   The edge (parent, operator) goes into the open list with the parent's
//   heuristic value, and the state is built and evaluated only when the
//   edge comes out. Most generated successors are never evaluated.
// - Preferred operators: edges through the operators of the parent's
//   relaxed plan also go into a second open list. The two lists take
//   turns; whenever the heuristic reaches a new low, the preferred list is
//   given the next 1000 turns.
// - Each open list is first in, first out among equal values.
// - Duplicate states are detected through the StateRegistry and never
//   reopened; states whose relaxed goal is unreachable are dead ends.
//
// The search is complete: on a finite task it ends with a plan or with
// kExhausted, which proves that no plan exists (relevance pruning is
// sound, search/relevance.h). Plans are not guaranteed shortest; with
// improve_plan (the default) the plan found is shortened by greedy action
// elimination (Fink and Yang 1992): an action is dropped, with the later
// actions that become inapplicable, whenever the rest still reaches the
// goal. It is a stepper like IterativeDeepeningSearch, and deterministic.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "search/ff_heuristic.h"
#include "search/ground_task.h"
#include "search/search.h"
#include "search/state_registry.h"
#include "search/successor_generator.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

class GreedyBestFirstSearch {
 public:
  // Analyses relevance, grounds the task and evaluates the initial state.
  // Keeps a reference to the domain: it must outlive the search.
  GreedyBestFirstSearch(const Domain& domain, const Universe& universe, const State& initial, const Goal& goal,
                        SearchOptions options);
  GreedyBestFirstSearch(const GreedyBestFirstSearch&) = delete;
  GreedyBestFirstSearch& operator=(const GreedyBestFirstSearch&) = delete;

  // Expands up to `node_budget` more states. Once it returns a final
  // status, later calls return the same status and do nothing.
  SearchStatus step(std::uint64_t node_budget);
  // Steps until a final status.
  SearchStatus run();

  SearchStatus status() const { return status_; }
  // Valid once status() is kSolved.
  const std::vector<Action>& plan() const { return plan_; }
  const SearchStatistics& statistics() const { return statistics_; }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  struct Edge {
    StateId parent;
    OperatorId op;
  };
  // Edges by integer key, first in first out among equal keys.
  class BucketQueue {
   public:
    void push(int key, Edge edge);
    bool empty() const { return size_ == 0; }
    Edge pop();  // the oldest edge of the lowest key; the queue must not be empty

   private:
    std::vector<std::vector<Edge>> buckets_;
    std::vector<std::size_t> heads_;
    std::size_t lowest_ = 0;
    std::size_t size_ = 0;
  };

  void expand(StateId id, const StateWord* state);
  bool pop(Edge& edge);
  bool budget_spent();
  void report_progress();
  void solved(StateId goal);
  void finish(SearchStatus status);
  std::vector<OperatorId> shortened(std::vector<OperatorId> ops) const;

  SearchOptions options_;
  std::vector<std::string> notes_;
  std::unique_ptr<GroundTask> task_;
  std::unique_ptr<SuccessorGenerator> successors_;
  std::unique_ptr<FfHeuristic> heuristic_;
  std::unique_ptr<StateRegistry> registry_;
  std::vector<StateId> parent_;  // by state id
  std::vector<OperatorId> via_;  // by state id: the operator that reached it
  BucketQueue open_[2];          // 0: every edge; 1: preferred edges
  int priority_[2] = {0, 0};     // the list with the lower priority takes the next turn
  std::vector<OperatorId> applicable_, preferred_;
  std::vector<std::uint64_t> preferred_mark_;  // by operator: the expansion that marked it preferred
  std::vector<StateWord> scratch_;
  SearchStatus status_ = SearchStatus::kInProgress;
  std::vector<Action> plan_;
  SearchStatistics statistics_;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point next_report_;
  std::uint64_t steps_since_clock_ = 0;  // the first step reads the clock (see budget_spent)
};

// Convenience: plans from the state to the goal with the given options
// (max_depth is ignored).
PlanResult find_greedy_plan(const Domain& domain, const Universe& universe, const State& initial, const Goal& goal,
                            const SearchOptions& options);

}  // namespace apprentice
