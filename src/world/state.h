// A State is an immutable set of facts, with value semantics: copying one
// copies a pointer, comparing two compares their facts, and the hash is
// computed once at construction. Changing a state makes a new one.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "world/fact.h"

namespace apprentice {

class State {
 public:
  State();
  // Takes any facts; duplicates are removed and the order does not matter.
  explicit State(std::vector<Fact> facts);

  bool holds(const Fact& fact) const;
  bool satisfies(const Literal& literal) const {
    return holds(literal.fact) == literal.positive;
  }
  // Sorted, without duplicates.
  std::span<const Fact> facts() const { return *facts_; }
  std::size_t size() const { return facts_->size(); }
  std::size_t hash() const { return hash_; }

  // A new state with `removed` taken out and then `added` put in.
  State with_changes(std::span<const Fact> removed, std::span<const Fact> added) const;

  friend bool operator==(const State& a, const State& b);
  friend bool operator<(const State& a, const State& b);

 private:
  std::shared_ptr<const std::vector<Fact>> facts_;
  std::size_t hash_ = 0;
};

struct StateHash {
  std::size_t operator()(const State& state) const { return state.hash(); }
};

}  // namespace apprentice
