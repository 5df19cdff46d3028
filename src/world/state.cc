#include "world/state.h"

#include <algorithm>

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
  std::vector<Fact> facts;
  facts.reserve(facts_->size() + added.size());
  for (const Fact& fact : *facts_) {
    if (std::find(removed.begin(), removed.end(), fact) == removed.end()) facts.push_back(fact);
  }
  facts.insert(facts.end(), added.begin(), added.end());
  return State(std::move(facts));
}

bool operator==(const State& a, const State& b) {
  if (a.facts_ == b.facts_) return true;
  return a.hash_ == b.hash_ && *a.facts_ == *b.facts_;
}

bool operator<(const State& a, const State& b) { return *a.facts_ < *b.facts_; }

}  // namespace apprentice
