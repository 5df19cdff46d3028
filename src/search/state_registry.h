// Packed states, each stored once and named by a dense id. States lie back
// to back in one array (words() words each); a power-of-two open-addressing
// table of ids finds a state by its contents. Registering a state copies
// its words and, amortized, allocates nothing.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "search/ground_task.h"

namespace apprentice {

using StateId = std::uint32_t;
inline constexpr StateId kNoState = 0xffffffffu;

class StateRegistry {
 public:
  explicit StateRegistry(std::size_t words);

  // The id of the state in `words`; registers it if new. `second` is true
  // when it was new. `words` must not point into the registry.
  std::pair<StateId, bool> insert(const StateWord* words);
  // Valid until the next insert.
  const StateWord* get(StateId id) const { return data_.data() + static_cast<std::size_t>(id) * words_; }
  std::size_t size() const { return count_; }
  // Bytes held by the states and the table.
  std::size_t memory_bytes() const;

 private:
  std::uint64_t hash(const StateWord* words) const;
  void grow();

  std::size_t words_;
  std::vector<StateWord> data_;
  std::vector<StateId> table_;  // kNoState marks an empty slot
  std::size_t count_ = 0;
};

}  // namespace apprentice
