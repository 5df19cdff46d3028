// Planning time against world size. Each world is the tidy kitchen (its 11
// places and 30 items) plus N extra items spread round-robin over the
// surfaces and receptacles; the goal is the one-object, four-step
//   (and (in ketchup1 fridge1) (closed fridge1)).
// With relevance pruning, search grounds only the goal's objects and the
// places, so the time should grow no worse than linearly in the number of
// objects (the remaining linear part is finding the relevant objects and
// projecting the state). Without pruning, every extra item adds actions at
// every node, which is what BM_PlanKetchupNoPruning shows.
//
// Run: build-core/bench/bench_search (see docs/benchmarks.md for figures).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "search/iterative_deepening.h"
#include "search/relevance.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace apprentice {
namespace {

struct GeneratedWorld {
  std::shared_ptr<const Domain> domain;
  Universe universe;
  State state;
  Goal goal;
};

// The kitchen with `extra` more items; built once per size.
const GeneratedWorld& world_with(int extra) {
  static std::map<int, std::unique_ptr<GeneratedWorld>> cache;
  auto& slot = cache[extra];
  if (slot) return *slot;

  auto scenario = load_scenario(std::filesystem::path(APPRENTICE_SOURCE_DIR) / "data/scenarios/tidy-kitchen.yaml");
  if (!scenario) {
    std::cerr << scenario.error().describe() << "\n";
    std::exit(2);
  }
  const World& base = scenario->world;
  const Vocabulary& v = base.vocabulary;
  auto world = std::make_unique<GeneratedWorld>();
  world->domain = base.domain;
  world->universe = *base.universe;
  std::vector<Fact> facts(base.state.facts().begin(), base.state.facts().end());
  std::vector<ObjectId> places = world->universe.of_kind(ObjectKind::kSurface);
  for (ObjectId r : world->universe.of_kind(ObjectKind::kReceptacle)) places.push_back(r);
  const TypeId item_type = *base.domain->find_type("item");
  for (int i = 0; i < extra; ++i) {
    ObjectId id = world->universe.add(
        ObjectInfo{"clutter" + std::to_string(i + 1), "clutter", ObjectKind::kItem, item_type, {}});
    ObjectId place = places[static_cast<std::size_t>(i) % places.size()];
    const bool on_surface = world->universe.info(place).kind == ObjectKind::kSurface;
    facts.push_back(Fact(v.grabbable, {id}));
    facts.push_back(Fact(on_surface ? v.on : v.in, {id, place}));
  }
  world->state = State(std::move(facts));
  auto goal = parse_goal(*world->domain, world->universe, "(and (in ketchup1 fridge1) (closed fridge1))");
  if (!goal) {
    std::cerr << goal.error().describe() << "\n";
    std::exit(2);
  }
  world->goal = std::move(*goal);
  slot = std::move(world);
  return *slot;
}

void plan_ketchup(benchmark::State& state, bool prune) {
  const GeneratedWorld& world = world_with(static_cast<int>(state.range(0)));
  SearchOptions options;
  options.prune_irrelevant = prune;
  PlanResult result;
  for (auto _ : state) {
    result = find_plan(*world.domain, world.universe, world.state, world.goal, options);
    benchmark::DoNotOptimize(result.plan.data());
  }
  if (result.status != SearchStatus::kSolved || result.plan.size() != 4) {
    state.SkipWithError("expected the four-step ketchup plan");
    return;
  }
  const auto objects = static_cast<benchmark::IterationCount>(world.universe.size());
  state.SetComplexityN(objects);
  state.counters["objects"] = static_cast<double>(objects);
  state.counters["relevant"] = static_cast<double>(result.statistics.relevant_objects);
  state.counters["ground_actions"] = static_cast<double>(result.statistics.ground_actions);
  state.counters["nodes_expanded"] = static_cast<double>(result.statistics.nodes_expanded);
}

// The only part of planning whose cost depends on the number of objects:
// finding the relevant ones and projecting the state onto them.
void BM_RelevanceAndProjection(benchmark::State& state) {
  const GeneratedWorld& world = world_with(static_cast<int>(state.range(0)));
  std::size_t kept = 0;
  for (auto _ : state) {
    std::vector<ObjectId> relevant = relevant_objects(*world.domain, world.universe, world.state, world.goal);
    State projected = project_state(world.state, relevant);
    kept = projected.size();
    benchmark::DoNotOptimize(kept);
  }
  state.SetComplexityN(static_cast<benchmark::IterationCount>(world.universe.size()));
  state.counters["objects"] = static_cast<double>(world.universe.size());
  state.counters["facts_kept"] = static_cast<double>(kept);
}

void BM_PlanKetchup(benchmark::State& state) { plan_ketchup(state, true); }
void BM_PlanKetchupNoPruning(benchmark::State& state) { plan_ketchup(state, false); }

// Arguments are the extra items; the complexity fit is over all objects.
BENCHMARK(BM_PlanKetchup)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_RelevanceAndProjection)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_PlanKetchupNoPruning)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace apprentice

BENCHMARK_MAIN();
