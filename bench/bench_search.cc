// Planning time against world size. Each world is a scenario's kitchen
// plus N extra items (clutter) spread round-robin over its surfaces and
// receptacles.
//
// - BM_PlanKetchup: iterative deepening (the paper's search) for the
//   one-object, four-step goal (and (in ketchup1 fridge1) (closed fridge1))
//   in the tidy kitchen. BM_PlanKetchupNoPruning shows why relevance
//   pruning matters.
// - BM_PlanWholeKitchen: greedy best-first search for the whole tidy
//   kitchen task (the 35 goal assertions of its intent) with 10^3, 10^4
//   and 10^5 extra items.
// - BM_PlanStackedDishes: the same for the whole task of
//   data/scenarios/stacked-dishes.yaml, where dishes interact, so the
//   analysis keeps them for every goal and prunes the clutter.
//
// With relevance pruning, search grounds only what can matter, so the time
// should grow no worse than linearly in the number of objects (the linear
// part is finding the relevant objects and projecting the state).
//
// Run: build/bench/bench_search (see docs/benchmarks.md for figures).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "search/greedy_best_first.h"
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
  Goal goal;       // the ketchup goal
  Goal task_goal;  // every goal assertion of the scenario's intent
};

// The scenario's kitchen with `extra` more items; built once per size.
const GeneratedWorld& world_with(const char* scenario_file, int extra) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<GeneratedWorld>> cache;
  auto& slot = cache[{scenario_file, extra}];
  if (slot) return *slot;

  auto scenario = load_scenario(std::filesystem::path(APPRENTICE_SOURCE_DIR) / "data/scenarios" / scenario_file);
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
  const TypeId item_type = *base.domain->find_type(type_name(ObjectKind::kItem));
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
  world->task_goal = Goal(scenario->goal_assertions());
  slot = std::move(world);
  return *slot;
}

const GeneratedWorld& world_with(int extra) { return world_with("tidy-kitchen.yaml", extra); }

// The counters every planning benchmark reports; the complexity fit is over
// all objects.
void report(benchmark::State& state, const GeneratedWorld& world, const PlanResult& result) {
  const auto objects = static_cast<benchmark::IterationCount>(world.universe.size());
  state.SetComplexityN(objects);
  state.counters["objects"] = static_cast<double>(objects);
  state.counters["relevant"] = static_cast<double>(result.statistics.relevant_objects);
  state.counters["ground_actions"] = static_cast<double>(result.statistics.ground_actions);
  state.counters["nodes_expanded"] = static_cast<double>(result.statistics.nodes_expanded);
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
  report(state, world, result);
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

// Greedy best-first search for a scenario's whole task. Every run checks
// that the plan replays to the goal and is no longer than `max_steps`.
void plan_whole_task(benchmark::State& state, const char* scenario_file, std::size_t max_steps) {
  const GeneratedWorld& world = world_with(scenario_file, static_cast<int>(state.range(0)));
  PlanResult result;
  for (auto _ : state) {
    result = find_greedy_plan(*world.domain, world.universe, world.state, world.task_goal, {});
    benchmark::DoNotOptimize(result.plan.data());
  }
  State replayed = world.state;
  for (const Action& a : result.plan) {
    if (!is_applicable(*world.domain, replayed, a)) {
      state.SkipWithError("the plan does not replay");
      return;
    }
    replayed = apply(*world.domain, replayed, a);
  }
  if (result.status != SearchStatus::kSolved || !world.task_goal.satisfied_by(replayed) ||
      result.plan.size() > max_steps) {
    state.SkipWithError("expected a plan that reaches the whole task's goal");
    return;
  }
  report(state, world, result);
  state.counters["steps"] = static_cast<double>(result.plan.size());
  state.counters["grounding_ms"] = result.statistics.grounding_ms;
}

void BM_PlanKetchup(benchmark::State& state) { plan_ketchup(state, true); }
void BM_PlanKetchupNoPruning(benchmark::State& state) { plan_ketchup(state, false); }
void BM_PlanWholeKitchen(benchmark::State& state) { plan_whole_task(state, "tidy-kitchen.yaml", 77); }
void BM_PlanStackedDishes(benchmark::State& state) { plan_whole_task(state, "stacked-dishes.yaml", 1000); }

// Arguments are the extra items; the complexity fit is over all objects.
BENCHMARK(BM_PlanKetchup)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_RelevanceAndProjection)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_PlanKetchupNoPruning)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanWholeKitchen)->Arg(0)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
BENCHMARK(BM_PlanStackedDishes)->Arg(0)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);

}  // namespace
}  // namespace apprentice

BENCHMARK_MAIN();
