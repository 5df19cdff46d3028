#include "search/state_registry.h"

#include <algorithm>

#include "util/check.h"

namespace apprentice {

StateRegistry::StateRegistry(std::size_t words) : words_(words), table_(1024, kNoState) {
  APPRENTICE_CHECK(words_ > 0);
  data_.reserve(1024 * words_);
}

std::uint64_t StateRegistry::hash(const StateWord* words) const {
  // Multiply-xorshift mixing per word (the finalizer of SplitMix64).
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ words_;
  for (std::size_t i = 0; i < words_; ++i) {
    std::uint64_t x = words[i] + 0x9e3779b97f4a7c15ULL * (i + 1);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    h = (h ^ (x ^ (x >> 31))) * 0x100000001b3ULL;
  }
  return h ^ (h >> 29);
}

std::pair<StateId, bool> StateRegistry::insert(const StateWord* words) {
  if ((count_ + 1) * 4 > table_.size() * 3) grow();
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = hash(words) & mask;; slot = (slot + 1) & mask) {
    const StateId id = table_[slot];
    if (id == kNoState) {
      APPRENTICE_CHECK_MSG(count_ < kNoState, "more states than a state id can name");
      const auto fresh = static_cast<StateId>(count_++);
      data_.insert(data_.end(), words, words + words_);
      table_[slot] = fresh;
      return {fresh, true};
    }
    if (std::equal(words, words + words_, get(id))) return {id, false};
  }
}

void StateRegistry::grow() {
  std::vector<StateId> bigger(table_.size() * 2, kNoState);
  const std::size_t mask = bigger.size() - 1;
  for (StateId id : table_) {
    if (id == kNoState) continue;
    std::size_t slot = hash(get(id)) & mask;
    while (bigger[slot] != kNoState) slot = (slot + 1) & mask;
    bigger[slot] = id;
  }
  table_.swap(bigger);
}

std::size_t StateRegistry::memory_bytes() const {
  return data_.capacity() * sizeof(StateWord) + table_.capacity() * sizeof(StateId);
}

}  // namespace apprentice
