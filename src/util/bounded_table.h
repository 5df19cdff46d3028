// A table of remembered answers that never grows past a capacity: when it
// is full, the next answer starts it again from empty. For caches fed by
// outside input (words from a page, a script), where an unbounded map
// would let a stream of distinct keys grow the process without end, and
// where an answer forgotten only costs looking it up again.
#pragma once

#include <cstddef>
#include <map>
#include <utility>

namespace apprentice::util {

template <typename Key, typename Value, typename Compare = std::less<>>
class BoundedTable {
 public:
  explicit BoundedTable(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

  // The answer kept for `key`, or nullptr. Valid until the next remember().
  template <typename K>
  const Value* find(const K& key) const {
    auto it = table_.find(key);
    return it == table_.end() ? nullptr : &it->second;
  }

  void remember(Key key, Value value) {
    if (table_.size() >= capacity_ && table_.find(key) == table_.end()) table_.clear();
    table_.insert_or_assign(std::move(key), std::move(value));
  }

  void clear() { table_.clear(); }
  std::size_t size() const { return table_.size(); }
  std::size_t capacity() const { return capacity_; }

 private:
  std::size_t capacity_;
  std::map<Key, Value, Compare> table_;
};

}  // namespace apprentice::util
