#include "world/state.h"

#include <algorithm>
#include <iterator>

namespace apprentice {

namespace {

std::size_t mix(std::size_t seed, std::size_t value) {
  // 64-bit variant of boost::hash_combine's constant-and-shift scheme.
  return seed ^ (value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2));
}

std::size_t hash_facts(const std::vector<Fact>& facts) {
  std::size_t seed = facts.size();
  for (const Fact& fact : facts) seed = mix(seed, hash_value(fact));
  return seed;
}

std::shared_ptr<const std::vector<Fact>> empty_facts() {
  static const auto kEmpty = std::make_shared<const std::vector<Fact>>();
  return kEmpty;
}

}  // namespace

std::size_t hash_value(const Fact& fact) {
  std::size_t seed = mix(fact.predicate, fact.arity);
  for (std::uint16_t i = 0; i < fact.arity; ++i) seed = mix(seed, fact.args[i]);
  return seed;
}

State::State() : facts_(empty_facts()), hash_(hash_facts(*facts_)) {}

State::State(std::vector<Fact> facts) {
  std::sort(facts.begin(), facts.end());
  facts.erase(std::unique(facts.begin(), facts.end()), facts.end());
  hash_ = hash_facts(facts);
  facts_ = std::make_shared<const std::vector<Fact>>(std::move(facts));
}

bool State::holds(const Fact& fact) const {
  return std::binary_search(facts_->begin(), facts_->end(), fact);
}

State State::with_changes(std::span<const Fact> removed, std::span<const Fact> added) const {
  // Linear in the state's size (a merge of sorted ranges), not n log n: the
  // simulator and the agent change states with millions of facts.
  std::vector<Fact> removed_sorted(removed.begin(), removed.end());
  std::sort(removed_sorted.begin(), removed_sorted.end());
  std::vector<Fact> added_sorted(added.begin(), added.end());
  std::sort(added_sorted.begin(), added_sorted.end());
  added_sorted.erase(std::unique(added_sorted.begin(), added_sorted.end()), added_sorted.end());
  std::vector<Fact> kept;
  kept.reserve(facts_->size());
  std::set_difference(facts_->begin(), facts_->end(), removed_sorted.begin(), removed_sorted.end(),
                      std::back_inserter(kept));
  std::vector<Fact> facts;
  facts.reserve(kept.size() + added_sorted.size());
  std::set_union(kept.begin(), kept.end(), added_sorted.begin(), added_sorted.end(), std::back_inserter(facts));
  State next;
  next.hash_ = hash_facts(facts);
  next.facts_ = std::make_shared<const std::vector<Fact>>(std::move(facts));
  return next;
}

bool operator==(const State& a, const State& b) {
  if (a.facts_ == b.facts_) return true;
  return a.hash_ == b.hash_ && *a.facts_ == *b.facts_;
}

bool operator<(const State& a, const State& b) { return *a.facts_ < *b.facts_; }

}  // namespace apprentice
