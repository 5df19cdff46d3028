// The speed of a decision and of opening the word vectors, the TidyBot
// benchmark's targets (issue 20): after loading, one decision takes at most
// 1 ms, and loading the vectors at most 100 ms (docs/benchmarks.md,
// "TidyBot", "Speed").
//
//   build/bench/bench_decision [--benchmark_filter=...]
//
// A decision is what the agent does for a thing it has no goal for
// (agent/agent_decision.cc, without the LLM and the cross-world analogy):
// the proposals of the likeness and induced-rule sources over the goals
// taught before (GoalProposer::propose), combined by decide(). The goals
// are each scenario's seen placements of the development half
// (APPRENTICE_TIDYBOT_SCENARIOS, else ../shared/data/tidybot-benchmark/
// scenarios-dev.yml beside the source tree); the things decided are its
// unseen objects.
//   BM_Decision/warm  one decision, with the scenario's rules induced and
//                     the names met before looked up (the agent's own
//                     caches, as in a session after its first things)
//   BM_Decision/cold  each scenario's decisions from fresh caches, per
//                     decision: inducing the rules and looking every name
//                     up in WordNet and the vectors are in it
//   BM_OpenVectors    opening the vectors file (mapping it, checking it)
//                     and one lookup
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "benchmark/tidybot_scenarios.h"
#include "benchmark/tidybot_world.h"
#include "language/lexicon.h"
#include "vectors/word_vectors.h"

namespace {

using namespace apprentice;
namespace tb = apprentice::benchmark;

struct Case {
  tb::BenchmarkWorld world;
  std::vector<GoalKnowledge> prior;
  std::vector<std::pair<GoalKey, ObjectId>> unseen;
};

struct Loaded {
  language::Lexicon lexicon = language::Lexicon::open_default();
  std::optional<vectors::WordVectors> vectors = vectors::open_default_vectors();
  std::vector<Case> cases;
  std::string error;
};

std::filesystem::path scenarios_path() {
  if (const char* path = std::getenv("APPRENTICE_TIDYBOT_SCENARIOS")) return path;
  return std::filesystem::path(APPRENTICE_SOURCE_DIR) / ".." / "shared" / "data" / "tidybot-benchmark" / "scenarios-dev.yml";
}

// Where a place of the world sends a thing.
Destination destination_at(const World& world, ObjectId place, bool closed) {
  const ObjectInfo& info = world.universe->info(place);
  Destination d{info.kind == ObjectKind::kReceptacle ? "in" : "on",
                GoalTemplateArgument{false, info.category, info.properties}, {}};
  if (closed) d.doors.push_back(GoalTemplateLiteral{"closed", true, {d.place}});
  return d;
}

const Loaded& loaded() {
  static Loaded* l = [] {
    auto* out = new Loaded;
    auto scenarios = tb::load_tidybot_scenarios(scenarios_path());
    if (!scenarios) {
      out->error = scenarios.error().describe();
      return out;
    }
    const auto domain = std::filesystem::path(APPRENTICE_SOURCE_DIR) / "data" / "domains" / "kitchen.pddl";
    for (const tb::TidyBotScenario& s : *scenarios) {
      std::vector<std::string> objects = s.seen_objects;
      objects.insert(objects.end(), s.unseen_objects.begin(), s.unseen_objects.end());
      auto world = tb::build_world(s, objects, domain, out->lexicon);
      if (!world) {
        out->error = world.error().describe();
        return out;
      }
      Case c{std::move(*world), {}, {}};
      const World& w = c.world.scenario.world;
      const std::string task = "tidy " + s.room, cart = w.universe->info(c.world.cart).category;
      for (const auto& [name, id] : c.world.objects) {
        const std::string& category = w.universe->info(id).category;
        GoalKey key{task, "clear", category, cart};
        const bool seen = std::find(s.seen_objects.begin(), s.seen_objects.end(), name) != s.seen_objects.end();
        if (!seen) {
          c.unseen.emplace_back(key, id);
          continue;
        }
        const IntentEntry* intent = c.world.scenario.find_intent("clear", category);
        if (intent == nullptr) continue;
        GoalKnowledge g;
        g.key = key;
        g.literals = destination_literals(destination_at(w, intent->place, intent->closed));
        c.prior.push_back(std::move(g));
      }
      out->cases.push_back(std::move(c));
    }
    return out;
  }();
  return *l;
}

// One decision, as the agent takes it for a thing with no goal.
Decision decide_for(const GoalProposer& proposer, const Case& c, const std::pair<GoalKey, ObjectId>& thing,
                    const DecisionPolicy& policy) {
  const World& w = c.world.scenario.world;
  std::vector<DestinationProposal> proposals = proposer.propose(w, thing.first, thing.second, {});
  const ObjectId away[] = {c.world.cart};
  return decide(proposals, place_count(w, away), policy);
}

void BM_DecisionWarm(::benchmark::State& state) {
  const Loaded& l = loaded();
  if (!l.error.empty() || l.cases.empty()) {
    state.SkipWithError(l.error.empty() ? "no scenarios" : l.error.c_str());
    return;
  }
  LexicalConcepts concepts(l.lexicon, l.vectors ? &*l.vectors : nullptr);
  std::vector<std::unique_ptr<GoalProposer>> proposers;
  for (const Case& c : l.cases) proposers.push_back(std::make_unique<GoalProposer>(concepts, c.prior));
  const DecisionPolicy policy = default_decision_policy();
  // Every decision once before timing: the caches are warm.
  std::vector<std::pair<std::size_t, std::size_t>> all;
  for (std::size_t i = 0; i < l.cases.size(); ++i)
    for (std::size_t j = 0; j < l.cases[i].unseen.size(); ++j) {
      all.emplace_back(i, j);
      ::benchmark::DoNotOptimize(decide_for(*proposers[i], l.cases[i], l.cases[i].unseen[j], policy));
    }
  std::size_t next = 0, acted = 0;
  for (auto _ : state) {
    const auto [i, j] = all[next];
    next = (next + 1) % all.size();
    Decision d = decide_for(*proposers[i], l.cases[i], l.cases[i].unseen[j], policy);
    acted += d.kind == Decision::Kind::kAct;
    ::benchmark::DoNotOptimize(d);
  }
  state.counters["things"] = static_cast<double>(all.size());
  state.counters["vectors"] = l.vectors ? 1 : 0;
}
BENCHMARK(BM_DecisionWarm)->Name("BM_Decision/warm")->Unit(::benchmark::kMicrosecond);

void BM_DecisionCold(::benchmark::State& state) {
  const Loaded& l = loaded();
  if (!l.error.empty() || l.cases.empty()) {
    state.SkipWithError(l.error.empty() ? "no scenarios" : l.error.c_str());
    return;
  }
  const DecisionPolicy policy = default_decision_policy();
  std::size_t decisions = 0;
  for (auto _ : state) {
    // Every scenario from fresh caches: the first decision of each induces
    // its rules, and every name is looked up anew.
    for (const Case& c : l.cases) {
      LexicalConcepts concepts(l.lexicon, l.vectors ? &*l.vectors : nullptr);
      GoalProposer proposer(concepts, c.prior);
      for (const auto& thing : c.unseen) {
        ::benchmark::DoNotOptimize(decide_for(proposer, c, thing, policy));
        ++decisions;
      }
    }
  }
  // Seconds per decision.
  state.counters["per_decision"] =
      ::benchmark::Counter(static_cast<double>(decisions), ::benchmark::Counter::kIsRate | ::benchmark::Counter::kInvert);
  state.counters["vectors"] = l.vectors ? 1 : 0;
}
BENCHMARK(BM_DecisionCold)->Name("BM_Decision/cold")->Unit(::benchmark::kMillisecond);

void BM_OpenVectors(::benchmark::State& state) {
  std::optional<std::filesystem::path> file;
  for (const std::filesystem::path& p : vectors::vectors_search_path())
    if (std::filesystem::exists(p)) {
      file = p;
      break;
    }
  if (!file) {
    state.SkipWithError("the word vectors are not installed: bash scripts/install-deps.sh && make");
    return;
  }
  for (auto _ : state) {
    auto opened = vectors::WordVectors::open(*file);
    if (!opened) {
      state.SkipWithError(opened.error().describe().c_str());
      return;
    }
    ::benchmark::DoNotOptimize(opened->similarity("banana", "apple"));
  }
}
BENCHMARK(BM_OpenVectors)->Unit(::benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
