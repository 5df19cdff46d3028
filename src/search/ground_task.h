// A STRIPS task ground over a set of objects and compiled for fast search.
// Every dynamic fact that some operator or the goal can touch is a
// proposition, numbered from 0; a state is a packed bit set of them (one
// bit per proposition, 64 to a word); static facts are settled at
// grounding and vanish. Each operator keeps its preconditions and effects
// as ranges of one flat array of proposition ids, so that testing and
// applying it touches a few cache lines and allocates nothing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "world/action.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

using PropositionId = std::uint32_t;
using OperatorId = std::uint32_t;
using StateWord = std::uint64_t;

inline bool test_bit(const StateWord* state, PropositionId p) { return (state[p >> 6] >> (p & 63)) & 1; }
inline void set_bit(StateWord* state, PropositionId p) { state[p >> 6] |= StateWord{1} << (p & 63); }
inline void clear_bit(StateWord* state, PropositionId p) { state[p >> 6] &= ~(StateWord{1} << (p & 63)); }

// [begin, end) in GroundTask's flat proposition array.
struct PropositionRange {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  std::uint32_t size() const { return end - begin; }
};

struct GroundOperator {
  Action action;
  PropositionRange requires_true;
  PropositionRange requires_false;  // negative preconditions
  PropositionRange adds;
  PropositionRange deletes;
};

class GroundTask {
 public:
  // Grounds every action over `objects` whose types fit and whose static
  // preconditions hold in `initial`, keeps those whose positive
  // preconditions are reachable when deletes are ignored, and numbers the
  // dynamic facts they and the goal use. `initial` should already be
  // projected onto `objects` (search/relevance.h).
  GroundTask(const Domain& domain, const Universe& universe, std::span<const ObjectId> objects,
             const State& initial, const Goal& goal);

  std::size_t proposition_count() const { return facts_.size(); }
  std::size_t words() const { return words_; }
  std::size_t operator_count() const { return operators_.size(); }
  const GroundOperator& op(OperatorId id) const { return operators_[id]; }
  std::span<const PropositionId> list(PropositionRange range) const {
    return {flat_.data() + range.begin, range.size()};
  }
  const Fact& fact(PropositionId p) const { return facts_[p]; }

  // The initial state, packed.
  const std::vector<StateWord>& initial() const { return initial_; }
  std::span<const PropositionId> goal_true() const { return goal_true_; }
  std::span<const PropositionId> goal_false() const { return goal_false_; }
  // A goal literal over a static predicate fails in the initial state: no
  // plan can exist.
  bool goal_statically_false() const { return goal_statically_false_; }

  bool applicable(const StateWord* state, OperatorId id) const;
  // Writes the successor into `out` (words() words); `out` may not alias `state`.
  void apply(const StateWord* state, OperatorId id, StateWord* out) const;
  bool is_goal(const StateWord* state) const;

 private:
  std::vector<Fact> facts_;  // by proposition id, sorted
  std::size_t words_ = 1;
  std::vector<GroundOperator> operators_;
  std::vector<PropositionId> flat_;
  std::vector<StateWord> initial_;
  std::vector<PropositionId> goal_true_, goal_false_;
  bool goal_statically_false_ = false;
};

}  // namespace apprentice
