#include "world/state.h"

#include <algorithm>
#include <limits>
#include <tuple>
#include <utility>

#include "util/check.h"

namespace apprentice {

namespace state_detail {

// An immutable node of the B+tree. A leaf (height 0) holds sorted facts; an
// inner node holds its children, all of height - 1, and in `facts` the first
// fact of each child's subtree.
struct Node {
  std::uint8_t height = 0;
  std::vector<Fact> facts;
  std::vector<std::shared_ptr<const Node>> children;

  std::size_t entries() const { return height == 0 ? facts.size() : children.size(); }
};

}  // namespace state_detail

using state_detail::Node;
using NodePtr = std::shared_ptr<const Node>;

namespace {

constexpr std::size_t kLeafMax = 64;
constexpr std::size_t kInnerMax = 32;
// Below these a non-root node is merged with a neighbour.
constexpr std::size_t kLeafMin = kLeafMax / 4;
constexpr std::size_t kInnerMin = kInnerMax / 4;

std::size_t min_entries(std::uint8_t height) { return height == 0 ? kLeafMin : kInnerMin; }

std::size_t mix(std::size_t seed, std::size_t value) {
  // 64-bit variant of boost::hash_combine's constant-and-shift scheme.
  return seed ^ (value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2));
}

// splitmix64's finalizer: spreads hash_value's bits so that sums of fact
// hashes rarely collide.
std::uint64_t spread(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

std::size_t fact_hash(const Fact& fact) { return static_cast<std::size_t>(spread(hash_value(fact))); }

NodePtr make_leaf(std::vector<Fact> facts) {
  auto node = std::make_shared<Node>();
  node->height = 0;
  node->facts = std::move(facts);
  return node;
}

NodePtr make_inner(std::uint8_t height, std::vector<NodePtr> children) {
  auto node = std::make_shared<Node>();
  node->height = height;
  node->facts.reserve(children.size());
  for (const NodePtr& child : children) node->facts.push_back(child->facts.front());
  node->children = std::move(children);
  return node;
}

// Cuts `count` entries into pieces of at most `max` (and about `target` when
// there are more than `max`), as even as possible; returns their sizes.
std::vector<std::size_t> piece_sizes(std::size_t count, std::size_t max, std::size_t target) {
  if (count <= max) return {count};
  const std::size_t pieces = (count + target - 1) / target;
  std::vector<std::size_t> sizes(pieces, count / pieces);
  for (std::size_t i = 0; i < count % pieces; ++i) ++sizes[i];
  return sizes;
}

// Makes nodes from the entries of one (possibly oversized) node, each of at
// most `max` entries (about three quarters of `max` when it must be cut), by
// `make`; appends them to out. For leaves the entries are facts, for inner
// nodes children.
template <typename Entry, typename Make>
void emit_nodes(std::vector<Entry> entries, std::size_t max, Make make, std::vector<NodePtr>& out) {
  if (entries.empty()) return;
  if (entries.size() <= max) {
    out.push_back(make(std::move(entries)));
    return;
  }
  std::size_t at = 0;
  for (std::size_t size : piece_sizes(entries.size(), max, max * 3 / 4)) {
    out.push_back(make(std::vector<Entry>(entries.begin() + at, entries.begin() + at + size)));
    at += size;
  }
}

void emit_leaves(std::vector<Fact> facts, std::vector<NodePtr>& out) {
  emit_nodes(std::move(facts), kLeafMax, make_leaf, out);
}

void emit_inner(std::uint8_t height, std::vector<NodePtr> children, std::vector<NodePtr>& out) {
  emit_nodes(std::move(children), kInnerMax,
             [height](std::vector<NodePtr> part) { return make_inner(height, std::move(part)); }, out);
}

}  // namespace

namespace state_detail {

// The order of a tree: Fact's own (predicate, arity, arguments), or, for the
// index by second argument, predicate, arity, second, first, third argument.
struct Order {
  bool by_second = false;
  bool operator()(const Fact& a, const Fact& b) const {
    if (!by_second) return a < b;
    return std::tie(a.predicate, a.arity, a.args[1], a.args[0], a.args[2]) <
           std::tie(b.predicate, b.arity, b.args[1], b.args[0], b.args[2]);
  }
};

}  // namespace state_detail

using state_detail::Order;

namespace {

// Sorted, unique changes, and what they did to the hash and the size.
struct Changes {
  std::span<const Fact> removed;
  std::span<const Fact> added;
  std::size_t hash_delta = 0;  // mod 2^64
  std::ptrdiff_t size_delta = 0;
};

// Applies the changes within [removed, added) to `node`; appends the nodes
// (of the same height, each within the size limits except that they may be
// underfull) that replace it to `out`: none if it became empty, `node`
// itself if nothing changed.
void apply(const NodePtr& node, std::span<const Fact> removed, std::span<const Fact> added, Order less,
           Changes& changes, std::vector<NodePtr>& out) {
  if (removed.empty() && added.empty()) {
    out.push_back(node);
    return;
  }
  if (node->height == 0) {
    const std::vector<Fact>& facts = node->facts;
    std::vector<Fact> kept;
    kept.reserve(facts.size());
    bool changed = false;
    auto r = removed.begin();
    for (const Fact& f : facts) {
      while (r != removed.end() && less(*r, f)) ++r;
      if (r != removed.end() && *r == f) {
        changes.hash_delta -= fact_hash(f);
        --changes.size_delta;
        changed = true;
        continue;
      }
      kept.push_back(f);
    }
    std::vector<Fact> merged;
    merged.reserve(kept.size() + added.size());
    auto k = kept.begin();
    for (const Fact& a : added) {
      while (k != kept.end() && less(*k, a)) merged.push_back(*k++);
      if (k != kept.end() && *k == a) continue;
      merged.push_back(a);
      changes.hash_delta += fact_hash(a);
      ++changes.size_delta;
      changed = true;
    }
    merged.insert(merged.end(), k, kept.end());
    if (!changed) {
      out.push_back(node);
      return;
    }
    emit_leaves(std::move(merged), out);
    return;
  }

  // An inner node: child i takes the changes below the first fact of child
  // i + 1 (child 0 also those below its own first fact).
  std::vector<NodePtr> children;
  children.reserve(node->children.size() + 2);
  bool changed = false;
  for (std::size_t i = 0; i < node->children.size(); ++i) {
    std::span<const Fact> r = removed, a = added;
    if (i + 1 < node->children.size()) {
      const Fact& next = node->facts[i + 1];
      r = r.first(static_cast<std::size_t>(std::lower_bound(r.begin(), r.end(), next, less) - r.begin()));
      a = a.first(static_cast<std::size_t>(std::lower_bound(a.begin(), a.end(), next, less) - a.begin()));
    }
    const std::size_t before = children.size();
    apply(node->children[i], r, a, less, changes, children);
    if (children.size() != before + 1 || children.back() != node->children[i]) changed = true;
    removed = removed.subspan(r.size());
    added = added.subspan(a.size());
  }
  if (!changed) {
    out.push_back(node);
    return;
  }
  // Merge underfull children with a neighbour (splitting again if that
  // makes one too big).
  const std::uint8_t child_height = static_cast<std::uint8_t>(node->height - 1);
  for (std::size_t i = 0; i < children.size();) {
    if (children.size() < 2 || children[i]->entries() >= min_entries(child_height)) {
      ++i;
      continue;
    }
    const std::size_t lo = i + 1 < children.size() ? i : i - 1;
    std::vector<NodePtr> joined;
    if (child_height == 0) {
      std::vector<Fact> facts = children[lo]->facts;
      facts.insert(facts.end(), children[lo + 1]->facts.begin(), children[lo + 1]->facts.end());
      emit_leaves(std::move(facts), joined);
    } else {
      std::vector<NodePtr> grandchildren = children[lo]->children;
      grandchildren.insert(grandchildren.end(), children[lo + 1]->children.begin(), children[lo + 1]->children.end());
      emit_inner(child_height, std::move(grandchildren), joined);
    }
    children.erase(children.begin() + static_cast<std::ptrdiff_t>(lo),
                   children.begin() + static_cast<std::ptrdiff_t>(lo + 2));
    children.insert(children.begin() + static_cast<std::ptrdiff_t>(lo), joined.begin(), joined.end());
    i = lo;
  }
  emit_inner(node->height, std::move(children), out);
}

// Puts nodes of one height under new roots until one is left.
NodePtr single_root(std::vector<NodePtr> nodes) {
  while (nodes.size() > 1) {
    std::vector<NodePtr> parents;
    const auto height = static_cast<std::uint8_t>(nodes.front()->height + 1);
    emit_inner(height, std::move(nodes), parents);
    nodes = std::move(parents);
  }
  if (nodes.empty()) return nullptr;
  NodePtr root = nodes.front();
  while (root->height > 0 && root->children.size() == 1) root = root->children.front();
  APPRENTICE_CHECK(root->height < state_detail::kMaxHeight);
  return root;
}

std::vector<Fact> sorted_unique(std::span<const Fact> facts, Order less = {}) {
  std::vector<Fact> out(facts.begin(), facts.end());
  std::sort(out.begin(), out.end(), less);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::size_t hash_value(const Fact& fact) {
  std::size_t seed = mix(fact.predicate, fact.arity);
  for (std::uint16_t i = 0; i < fact.arity; ++i) seed = mix(seed, fact.args[i]);
  return seed;
}

// ---- FactIterator ----

const Fact& FactIterator::operator*() const {
  const Frame& leaf = path_[depth_ - 1];
  return leaf.node->facts[leaf.index];
}

void FactIterator::descend_leftmost() {
  while (path_[depth_ - 1].node->height > 0) {
    const Frame& top = path_[depth_ - 1];
    path_[depth_] = Frame{top.node->children[top.index].get(), 0};
    ++depth_;
  }
}

void FactIterator::settle() {
  while (depth_ > 0 && path_[depth_ - 1].index >= path_[depth_ - 1].node->entries()) {
    --depth_;
    if (depth_ > 0) ++path_[depth_ - 1].index;
  }
  if (depth_ > 0) descend_leftmost();
}

FactIterator& FactIterator::operator++() {
  ++path_[depth_ - 1].index;
  if (path_[depth_ - 1].index >= path_[depth_ - 1].node->facts.size()) settle();
  return *this;
}

// ---- State ----

namespace {

// A tree of facts already sorted (in its order) and unique.
NodePtr build(std::vector<Fact> facts) {
  std::vector<NodePtr> leaves;
  emit_leaves(std::move(facts), leaves);
  return single_root(std::move(leaves));
}

// The facts of two or more arguments, in the order of the index by second
// argument.
std::vector<Fact> second_index_facts(std::span<const Fact> facts) {
  std::vector<Fact> out;
  for (const Fact& f : facts)
    if (f.arity >= 2) out.push_back(f);
  std::sort(out.begin(), out.end(), Order{true});
  return out;
}

}  // namespace

State::State(std::vector<Fact> facts) {
  std::sort(facts.begin(), facts.end());
  facts.erase(std::unique(facts.begin(), facts.end()), facts.end());
  size_ = facts.size();
  for (const Fact& f : facts) hash_sum_ += fact_hash(f);
  by_second_ = build(second_index_facts(facts));
  root_ = build(std::move(facts));
}

std::size_t State::hash() const { return static_cast<std::size_t>(spread(mix(size_, hash_sum_))); }

FactIterator State::lower_bound(const state_detail::Node* root, const Fact& fact, bool by_second) {
  const Order less{by_second};
  FactIterator it;
  if (!root) return it;
  const Node* node = root;
  while (true) {
    std::uint32_t index;
    if (node->height == 0) {
      index = static_cast<std::uint32_t>(std::lower_bound(node->facts.begin(), node->facts.end(), fact, less) -
                                         node->facts.begin());
    } else {
      // The last child whose first fact is <= fact (or the first child).
      auto after = std::upper_bound(node->facts.begin(), node->facts.end(), fact, less);
      index = after == node->facts.begin() ? 0u : static_cast<std::uint32_t>(after - node->facts.begin() - 1);
    }
    it.path_[it.depth_++] = FactIterator::Frame{node, index};
    if (node->height == 0) break;
    node = node->children[index].get();
  }
  if (it.path_[it.depth_ - 1].index >= node->facts.size()) it.settle();
  return it;
}

bool State::holds(const Fact& fact) const {
  if (!root_) return false;
  const Node* node = root_.get();
  while (node->height > 0) {
    auto after = std::upper_bound(node->facts.begin(), node->facts.end(), fact);
    if (after == node->facts.begin()) return false;
    node = node->children[static_cast<std::size_t>(after - node->facts.begin() - 1)].get();
  }
  return std::binary_search(node->facts.begin(), node->facts.end(), fact);
}

FactRange State::facts() const {
  FactIterator begin;
  if (root_) {
    begin.path_[0] = FactIterator::Frame{root_.get(), 0};
    begin.depth_ = 1;
    begin.descend_leftmost();
  }
  return FactRange(root_, begin, FactIterator());
}

FactRange State::facts_between(const Fact& lowest, const Fact& above) const {
  if (!(lowest < above)) return FactRange(root_, FactIterator(), FactIterator());
  return FactRange(root_, lower_bound(root_.get(), lowest, false), lower_bound(root_.get(), above, false));
}

FactRange State::facts_from(const Fact& lowest) const {
  return FactRange(root_, lower_bound(root_.get(), lowest, false), FactIterator());
}

FactRange State::facts_of(PredicateId predicate) const {
  Fact lowest;
  lowest.predicate = predicate;
  if (predicate == std::numeric_limits<PredicateId>::max()) return facts_from(lowest);
  Fact above;
  above.predicate = static_cast<PredicateId>(predicate + 1);
  return facts_between(lowest, above);
}

namespace {

// [lowest, above): the facts of `predicate` and `arity` whose argument in
// `slot` is `value`, in the order that sorts by that slot first.
std::pair<Fact, Fact> slot_interval(PredicateId predicate, std::uint16_t arity, std::size_t slot, ObjectId value) {
  Fact lowest;
  lowest.predicate = predicate;
  lowest.arity = arity;
  lowest.args[slot] = value;
  Fact above = lowest;
  if (value == std::numeric_limits<ObjectId>::max()) {
    above.args[slot] = 0;
    ++above.arity;  // every fact of this predicate with one more argument sorts after
  } else {
    above.args[slot] = value + 1;
  }
  return {lowest, above};
}

}  // namespace

FactRange State::facts_of(PredicateId predicate, std::uint16_t arity, ObjectId first) const {
  APPRENTICE_CHECK(arity >= 1 && arity <= kMaxArity);
  const auto [lowest, above] = slot_interval(predicate, arity, 0, first);
  return facts_between(lowest, above);
}

FactRange State::facts_with_second(PredicateId predicate, std::uint16_t arity, ObjectId second) const {
  APPRENTICE_CHECK(arity >= 2 && arity <= kMaxArity);
  const auto [lowest, above] = slot_interval(predicate, arity, 1, second);
  return FactRange(by_second_, lower_bound(by_second_.get(), lowest, true),
                   lower_bound(by_second_.get(), above, true));
}

State State::with_changes(std::span<const Fact> removed, std::span<const Fact> added) const {
  if (removed.empty() && added.empty()) return *this;
  const std::vector<Fact> removed_sorted = sorted_unique(removed);
  const std::vector<Fact> added_sorted = sorted_unique(added);
  Changes changes;
  std::vector<NodePtr> nodes;
  if (root_) {
    apply(root_, removed_sorted, added_sorted, Order{}, changes, nodes);
  } else {
    for (const Fact& a : added_sorted) changes.hash_delta += fact_hash(a);
    changes.size_delta = static_cast<std::ptrdiff_t>(added_sorted.size());
    emit_leaves(added_sorted, nodes);
  }
  if (nodes.size() == 1 && nodes.front() == root_) return *this;
  State next;
  next.root_ = single_root(std::move(nodes));
  next.size_ = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(size_) + changes.size_delta);
  next.hash_sum_ = hash_sum_ + changes.hash_delta;
  // The same changes to the index by second argument.
  const std::vector<Fact> removed_second = second_index_facts(removed_sorted);
  const std::vector<Fact> added_second = second_index_facts(added_sorted);
  if (!by_second_) {
    next.by_second_ = build(added_second);
  } else if (removed_second.empty() && added_second.empty()) {
    next.by_second_ = by_second_;
  } else {
    Changes ignored;
    std::vector<NodePtr> second_nodes;
    apply(by_second_, removed_second, added_second, Order{true}, ignored, second_nodes);
    next.by_second_ = single_root(std::move(second_nodes));
  }
  return next;
}

namespace state_detail {

// If a and b are both at the first fact of one same subtree (shared by the
// two states), moves both past it and returns true.
bool skip_shared(FactIterator& a, FactIterator& b) {
  // Frames from the leaf upwards: level h is path_[depth_ - 1 - h]. An
  // iterator is at the start of its level-h node when every frame from the
  // leaf up to that node has index 0.
  int best = -1;
  for (int h = 0; h < a.depth_ && h < b.depth_; ++h) {
    const FactIterator::Frame& fa = a.path_[a.depth_ - 1 - h];
    const FactIterator::Frame& fb = b.path_[b.depth_ - 1 - h];
    if (fa.index != 0 || fb.index != 0) break;
    if (fa.node == fb.node) best = h;
  }
  if (best < 0) return false;
  for (FactIterator* it : {&a, &b}) {
    it->depth_ = static_cast<std::uint8_t>(it->depth_ - 1 - best);  // drop the shared node and below
    if (it->depth_ > 0) ++it->path_[it->depth_ - 1].index;
    it->settle();
  }
  return true;
}

}  // namespace state_detail

using state_detail::skip_shared;

bool operator==(const State& a, const State& b) {
  if (a.root_ == b.root_) return true;
  if (a.size_ != b.size_ || a.hash_sum_ != b.hash_sum_) return false;
  const FactRange ra = a.facts(), rb = b.facts();
  FactIterator i = ra.begin(), j = rb.begin();
  const FactIterator end;
  while (i != end && j != end) {
    if (skip_shared(i, j)) continue;
    if (!(*i == *j)) return false;
    ++i;
    ++j;
  }
  return i == end && j == end;
}

bool operator<(const State& a, const State& b) {
  if (a.root_ == b.root_) return false;
  const FactRange ra = a.facts(), rb = b.facts();
  FactIterator i = ra.begin(), j = rb.begin();
  const FactIterator end;
  while (i != end && j != end) {
    if (skip_shared(i, j)) continue;
    if (!(*i == *j)) return *i < *j;
    ++i;
    ++j;
  }
  return i == end && j != end;
}

}  // namespace apprentice
