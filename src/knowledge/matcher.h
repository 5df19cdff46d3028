// Proposes and selects actions from learned rules, given the current state,
// goal, subtask and object of interest.
//
// Rules are indexed by the shape of their goal (which predicates, positive
// or negative), by the category their goal pattern tests, if any, and by
// the subtask they test, if any, so that a query looks only at rules that
// could match this goal in this subtask. The cost of a query grows with the
// number of rules in the few buckets it reads, not with all the rules known
// (bench/bench_matcher.cc, docs/benchmarks.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "knowledge/rule.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

struct Proposal {
  Action action;
  int steps_to_goal = 0;
  std::size_t rule_index = 0;  // into RuleMatcher::rules()
};

struct MatchQuery {
  const State* state = nullptr;
  const Goal* goal = nullptr;
  ObjectId object_of_interest = 0;
  std::string_view subtask;
};

class RuleMatcher {
 public:
  // Keeps references: domain and universe must outlive the matcher's use.
  RuleMatcher() = default;

  // Adds a rule unless an identical one (same signature) is known; returns
  // whether it was added.
  bool add(const Domain& domain, Rule rule);
  const std::vector<Rule>& rules() const { return rules_; }
  std::size_t size() const { return rules_.size(); }

  // Every action some rule proposes, each once, fewest steps first.
  std::vector<Proposal> propose(const Domain& domain, const Universe& universe,
                                const MatchQuery& query) const;
  // The preferred proposal: fewest steps to the goal, then the earliest rule.
  std::optional<Proposal> select(const Domain& domain, const Universe& universe,
                                 const MatchQuery& query) const;

 private:
  // shape|category|subtask; category "*" and subtask "" for rules that test none.
  static std::string bucket_key(std::string_view shape, std::string_view category, std::string_view subtask);
  static std::string goal_shape(const std::vector<Literal>& goal);

  std::vector<Rule> rules_;
  std::unordered_map<std::string, std::vector<std::size_t>> buckets_;
  std::unordered_map<std::string, bool> signatures_;
};

}  // namespace apprentice
