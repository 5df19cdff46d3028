// State at large n (docs/benchmarks.md, "State"): one action's change
// (with_changes: two facts out, two in, as a pick-up does), the hash, a
// copy, holds, the indexed queries and equality of states that share most
// of their tree, at n = 10^3 .. 10^6 facts. The states are built once per
// size, outside the timed loops. Every per-operation figure should grow
// like log n; before the B+tree (a sorted vector re-hashed in full) one
// with_changes cost O(n).
//
// Run: build/bench/bench_state
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "world/state.h"

namespace apprentice {
namespace {

constexpr PredicateId kOn = 0;
constexpr PredicateId kIn = 1;
constexpr PredicateId kClosed = 2;

// n facts shaped like a kitchen: (on item place) for most items, (in item
// place) for the rest, a few (closed place).
const State& kitchen_state(std::int64_t n) {
  static std::map<std::int64_t, State> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  std::vector<Fact> facts;
  for (std::int64_t i = 0; i < n; ++i) {
    const auto item = static_cast<ObjectId>(100 + i);
    facts.push_back(Fact(i % 3 == 0 ? kIn : kOn, {item, static_cast<ObjectId>(i % 11)}));
  }
  for (ObjectId p = 0; p < 5; ++p) facts.push_back(Fact(kClosed, {p}));
  return cache.emplace(n, State(std::move(facts))).first->second;
}

// The change of moving one item: (on x p) out, (in x q) in.
std::pair<Fact, Fact> move_of(std::int64_t n, std::mt19937& rng) {
  const auto i = std::uniform_int_distribution<std::int64_t>(0, n - 1)(rng);
  const auto item = static_cast<ObjectId>(100 + i);
  const auto place = static_cast<ObjectId>(i % 11);
  return {Fact(i % 3 == 0 ? kIn : kOn, {item, place}), Fact(kClosed, {item})};
}

void BM_WithChanges(benchmark::State& bench) {
  const State& start = kitchen_state(bench.range(0));
  std::mt19937 rng(1);
  for (auto _ : bench) {
    auto [out, in] = move_of(bench.range(0), rng);
    State next = start.with_changes(std::span<const Fact>(&out, 1), std::span<const Fact>(&in, 1));
    benchmark::DoNotOptimize(next.hash());
  }
}
BENCHMARK(BM_WithChanges)->RangeMultiplier(10)->Range(1000, 1000000);

// A run of actions, each on the state the last one made (as the simulator
// does): the cost per action.
void BM_WithChangesChained(benchmark::State& bench) {
  State state = kitchen_state(bench.range(0));
  std::mt19937 rng(2);
  for (auto _ : bench) {
    auto [out, in] = move_of(bench.range(0), rng);
    state = state.with_changes(std::span<const Fact>(&out, 1), std::span<const Fact>(&in, 1));
    benchmark::DoNotOptimize(state.hash());
  }
}
BENCHMARK(BM_WithChangesChained)->RangeMultiplier(10)->Range(1000, 1000000);

void BM_HashAndCopy(benchmark::State& bench) {
  const State& start = kitchen_state(bench.range(0));
  for (auto _ : bench) {
    State copy = start;
    benchmark::DoNotOptimize(copy.hash());
  }
}
BENCHMARK(BM_HashAndCopy)->RangeMultiplier(10)->Range(1000, 1000000);

void BM_Holds(benchmark::State& bench) {
  const State& start = kitchen_state(bench.range(0));
  std::mt19937 rng(3);
  for (auto _ : bench) {
    auto [present, absent] = move_of(bench.range(0), rng);
    benchmark::DoNotOptimize(start.holds(present) && !start.holds(absent));
  }
}
BENCHMARK(BM_Holds)->RangeMultiplier(10)->Range(1000, 1000000);

// Where one item is (facts_of by first argument) and what is in one place's
// first item (facts_with_second): the queries that replaced full scans.
void BM_IndexedQueries(benchmark::State& bench) {
  const State& start = kitchen_state(bench.range(0));
  std::mt19937 rng(4);
  for (auto _ : bench) {
    auto [fact, unused] = move_of(bench.range(0), rng);
    benchmark::DoNotOptimize(start.facts_of(fact.predicate, 2, fact.args[0]).front());
    benchmark::DoNotOptimize(start.facts_with_second(kOn, 2, fact.args[1]).front());
  }
}
BENCHMARK(BM_IndexedQueries)->RangeMultiplier(10)->Range(1000, 1000000);

// Equality of two equal states reached by different changes from one
// start: they share all but a few leaves, which is all that is compared.
void BM_EqualSharedStates(benchmark::State& bench) {
  const State& start = kitchen_state(bench.range(0));
  std::mt19937 rng(5);
  auto [a, b] = move_of(bench.range(0), rng);
  const State one = start.with_changes(std::span<const Fact>(&a, 1), std::span<const Fact>(&b, 1));
  const State other = start.with_changes({}, std::span<const Fact>(&b, 1)).with_changes(std::span<const Fact>(&a, 1), {});
  for (auto _ : bench) benchmark::DoNotOptimize(one == other);
  if (!(one == other)) bench.SkipWithError("the states should be equal");
}
BENCHMARK(BM_EqualSharedStates)->RangeMultiplier(10)->Range(1000, 1000000);

}  // namespace
}  // namespace apprentice

BENCHMARK_MAIN();
