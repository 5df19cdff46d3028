// A State is an immutable set of facts, with value semantics: copying one
// copies a pointer, comparing two compares their facts, and "changing" a
// state makes a new one.
//
// Representation: a persistent B+tree. Leaves hold up to 64 sorted facts,
// inner nodes up to 32 children; nodes are immutable and shared between
// states. `with_changes` copies only the paths to the leaves it touches, so
// one action on a state of n facts costs O(k log n) for k changed facts,
// not O(n), and the old state stays valid. The hash is the sum of a per-fact
// hash (order-independent), kept up to date by adding and subtracting only
// the facts that actually changed. A second tree indexes the facts of two
// or more arguments by their second argument (what is in fridge1), kept up
// to date the same way. Equality and ordering mean what they
// mean for the sorted sequences of facts; equal subtrees that two states
// share are skipped when comparing them.
//
// `facts()` and the range queries return a FactRange: a forward range over
// the facts in sorted order (Fact's operator<: predicate, arity, then
// arguments). A range keeps the state's tree alive, so it may outlive the
// State it came from. (Before, facts() returned a std::span over a sorted
// vector; callers that only iterate need no change.)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <span>
#include <vector>

#include "world/fact.h"

namespace apprentice {

class FactIterator;
namespace state_detail {
struct Node;
bool skip_shared(FactIterator& a, FactIterator& b);
inline constexpr std::size_t kMaxHeight = 12;  // 2 * 16^11 leaves at least: more than memory
}  // namespace state_detail

// A position in a State's facts: a path from the root to a leaf.
class FactIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = Fact;
  using difference_type = std::ptrdiff_t;
  using pointer = const Fact*;
  using reference = const Fact&;

  FactIterator() = default;  // the end of any range

  reference operator*() const;
  pointer operator->() const { return &**this; }
  FactIterator& operator++();
  FactIterator operator++(int) {
    FactIterator old = *this;
    ++*this;
    return old;
  }
  friend bool operator==(const FactIterator& a, const FactIterator& b) {
    if (a.depth_ == 0 || b.depth_ == 0) return a.depth_ == b.depth_;
    return a.path_[a.depth_ - 1].node == b.path_[b.depth_ - 1].node &&
           a.path_[a.depth_ - 1].index == b.path_[b.depth_ - 1].index;
  }

 private:
  friend class State;
  friend bool state_detail::skip_shared(FactIterator& a, FactIterator& b);
  struct Frame {
    const state_detail::Node* node = nullptr;
    std::uint32_t index = 0;
  };
  // Moves from the frame at depth_ - 1 (past its last entry) to the next
  // leaf's first fact, or to the end.
  void settle();
  void descend_leftmost();

  std::array<Frame, state_detail::kMaxHeight> path_{};
  std::uint8_t depth_ = 0;  // 0: the end
};

// Sorted facts [begin, end) of one State; keeps that state's facts alive.
class FactRange {
 public:
  FactRange() = default;
  FactRange(std::shared_ptr<const state_detail::Node> root, FactIterator begin, FactIterator end)
      : root_(std::move(root)), begin_(begin), end_(end) {}

  FactIterator begin() const { return begin_; }
  FactIterator end() const { return end_; }
  bool empty() const { return begin_ == end_; }
  const Fact& front() const { return *begin_; }
  // O(size): counts the facts.
  std::size_t size() const { return static_cast<std::size_t>(std::distance(begin_, end_)); }

 private:
  std::shared_ptr<const state_detail::Node> root_;
  FactIterator begin_;
  FactIterator end_;
};

class State {
 public:
  State() = default;
  // Takes any facts; duplicates are removed and the order does not matter.
  explicit State(std::vector<Fact> facts);

  // O(log n).
  bool holds(const Fact& fact) const;
  bool satisfies(const Literal& literal) const {
    return holds(literal.fact) == literal.positive;
  }
  // All facts, sorted, without duplicates.
  FactRange facts() const;
  // The facts f with lowest <= f < above, sorted: O(log n) to find, then
  // O(1) per fact.
  FactRange facts_between(const Fact& lowest, const Fact& above) const;
  // The facts f with lowest <= f, sorted.
  FactRange facts_from(const Fact& lowest) const;
  // Every fact of `predicate` (any arity).
  FactRange facts_of(PredicateId predicate) const;
  // Every fact of `predicate` with `arity` arguments whose first is `first`,
  // such as every (in mug1 ?place).
  FactRange facts_of(PredicateId predicate, std::uint16_t arity, ObjectId first) const;

  // Every fact of `predicate` with `arity` (2 or 3) arguments whose second
  // is `second`, such as every (in ?item fridge1): O(log n) to find, from an
  // index kept by second argument. Sorted by first argument, then third.
  FactRange facts_with_second(PredicateId predicate, std::uint16_t arity, ObjectId second) const;

  std::size_t size() const { return size_; }
  std::size_t hash() const;

  // A new state with `removed` taken out and then `added` put in: a fact in
  // both ends up present. O((|removed| + |added|) log n).
  State with_changes(std::span<const Fact> removed, std::span<const Fact> added) const;

  // True when the two states are the same tree (a copy): for tests.
  bool shares_root_with(const State& other) const { return root_ == other.root_; }

  friend bool operator==(const State& a, const State& b);
  friend bool operator<(const State& a, const State& b);

 private:
  static FactIterator lower_bound(const state_detail::Node* root, const Fact& fact, bool by_second);

  std::shared_ptr<const state_detail::Node> root_;  // null: no facts
  // The facts of two or three arguments again, ordered by predicate, arity,
  // second, first and third argument. Not part of the value: a function of
  // root_.
  std::shared_ptr<const state_detail::Node> by_second_;
  std::size_t size_ = 0;
  std::size_t hash_sum_ = 0;  // sum of fact_hash over the facts, mod 2^64
};

struct StateHash {
  std::size_t operator()(const State& state) const { return state.hash(); }
};

}  // namespace apprentice
