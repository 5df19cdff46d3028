// RuleMatcher::select as knowledge grows: 10, 1,000 and 100,000 rules.
//
// The rules are what a long-lived agent would accumulate: the real rules
// learned in tidy-kitchen.yaml (kPaper and kFull, from the ceramic plate,
// the paper plate and the ceramic bowl), then kPaper-style copies of them
// for ever more synthetic receptacle categories ("receptacle-123") across
// 20 synthetic subtasks (open, put-in and close per receptacle; one
// pick-up rule per synthetic surface, one surface per 50 receptacles), and
// a kFull rule per 100 (a take-out rule for a synthetic source category).
// The matcher indexes rules by goal shape and the category their goal
// tests, so these spread over buckets the way a growing knowledge base
// does.
//
// BM_SelectRealistic: the metal fork after the ceramic plate, goal
// (and (in metal-fork1 dishwasher1) (closed dishwasher1)) in subtask clear,
// from the kitchen after the plate was cleared: select must return
// (open dishwasher1). It reads the buckets of its goal shape for "*",
// "metal-fork" and "dishwasher".
//
// BM_SelectOneBucket: the worst case. Every rule sits in the one bucket
// the query reads (no category in its goal, subtask clear) and fails only
// late, on the category of the surface it binds, so that each rule costs a
// partial unification: select is then linear in the number of rules.
//
// Run: build/bench/bench_matcher (figures in docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "knowledge/learning.h"
#include "knowledge/matcher.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace apprentice {
namespace {

const Scenario& kitchen() {
  static const Scenario scenario = [] {
    auto loaded = load_scenario(std::filesystem::path(APPRENTICE_SOURCE_DIR) / "data/scenarios/tidy-kitchen.yaml");
    if (!loaded) {
      std::cerr << loaded.error().describe() << "\n";
      std::exit(2);
    }
    return std::move(*loaded);
  }();
  return scenario;
}

Action parse(const World& world, const char* text) {
  auto a = parse_action(*world.domain, *world.universe, text);
  if (!a) {
    std::cerr << a.error().describe() << "\n";
    std::exit(2);
  }
  return *a;
}

Goal parse_goal_or_die(const World& world, const char* text) {
  auto g = parse_goal(*world.domain, *world.universe, text);
  if (!g) {
    std::cerr << g.error().describe() << "\n";
    std::exit(2);
  }
  return *g;
}

std::vector<Rule> learn_episode(const World& world, const State& initial, const char* object, const char* goal,
                                const char* subtask, std::vector<const char*> actions, Generalization g) {
  Episode episode;
  episode.initial = initial;
  for (const char* a : actions) {
    episode.actions.push_back(parse(world, a));
    episode.sources.push_back("bench");
  }
  episode.goal = parse_goal_or_die(world, goal);
  episode.object_of_interest = *world.universe->find(object);
  episode.subtask = subtask;
  episode.object_description = object;
  return learn_policy_rules(*world.domain, *world.universe, episode, g);
}

// The rules really learned in the kitchen: [0..4) plate kPaper (close,
// put-in, pick-up, open), then paper plate, bowl, and the kFull ones.
std::vector<Rule> real_rules() {
  const World& w = kitchen().world;
  std::vector<Rule> out;
  for (Generalization g : {Generalization::kPaper, Generalization::kFull}) {
    for (auto& r : learn_episode(w, w.state, "ceramic-plate1", "(and (in ceramic-plate1 dishwasher1) (closed dishwasher1))",
                                 "clear", {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)",
                                           "(put-in ceramic-plate1 dishwasher1)", "(close dishwasher1)"}, g))
      out.push_back(std::move(r));
    for (auto& r : learn_episode(w, w.state, "paper-plate1", "(in paper-plate1 garbage1)", "clear",
                                 {"(pick-up paper-plate1 table1)", "(put-in paper-plate1 garbage1)"}, g))
      out.push_back(std::move(r));
    for (auto& r : learn_episode(w, w.state, "ceramic-bowl1", "(and (in ceramic-bowl1 cupboard1) (closed cupboard1))",
                                 "unload", {"(open cupboard1)", "(pick-up-from ceramic-bowl1 dish-rack1)",
                                            "(put-in ceramic-bowl1 cupboard1)", "(close cupboard1)"}, g))
      out.push_back(std::move(r));
  }
  return out;
}

// Sets the category of the variable named `name`.
void set_category(Rule& rule, const std::string& name, const std::string& category) {
  for (RuleVariable& v : rule.variables)
    if (v.name == name) v.category = category;
}

std::unique_ptr<RuleMatcher> realistic(std::size_t n) {
  const Domain& domain = *kitchen().world.domain;
  std::vector<Rule> real = real_rules();
  auto m = std::make_unique<RuleMatcher>();
  for (std::size_t i = 0; i < real.size() && m->size() < n; ++i) m->add(domain, real[i]);
  // Templates: the plate's kPaper close, put-in, pick-up and open; the
  // bowl's kFull take-out rule.
  const Rule& close = real[0];
  const Rule& put_in = real[1];
  const Rule& pick_up = real[2];
  const Rule& open = real[3];
  const Rule* take_out = nullptr;
  for (const Rule& r : real)
    if (domain.actions[r.action].name == "pick-up-from" && !r.subtask) take_out = &r;
  for (std::size_t i = 0; m->size() < n; ++i) {
    const std::string subtask = "subtask-" + std::to_string(i % 20);
    const std::string receptacle = "receptacle-" + std::to_string(i);
    for (const Rule* t : {&open, &put_in, &close}) {
      if (m->size() >= n) break;
      Rule r = *t;
      r.subtask = subtask;
      set_category(r, "?r", receptacle);
      m->add(domain, std::move(r));
    }
    if (i % 50 == 0 && m->size() < n) {
      Rule r = pick_up;
      r.subtask = subtask;
      set_category(r, "?s", "surface-" + std::to_string(i / 50));
      m->add(domain, std::move(r));
    }
    if (i % 100 == 0 && take_out && m->size() < n) {
      // A kFull rule with an extra test (a source it was learned from):
      // no goal category, so it lands in the shared "*" bucket.
      Rule r = *take_out;
      r.steps_to_goal = 3 + static_cast<int>(i / 100) % 5;
      set_category(r, "?r2", "source-" + std::to_string(i / 100));
      m->add(domain, std::move(r));
    }
  }
  return m;
}

std::unique_ptr<RuleMatcher> one_bucket(std::size_t n) {
  const Domain& domain = *kitchen().world.domain;
  Rule pick_up = real_rules()[2];  // kPaper, subtask clear, category(?s)=table
  auto m = std::make_unique<RuleMatcher>();
  for (std::size_t i = 0; m->size() < n; ++i) {
    Rule r = pick_up;
    set_category(r, "?s", "surface-" + std::to_string(i));
    // The open rule's conditions, so the rule reaches the surface test in
    // the queried state (dishwasher closed).
    r.conditions = real_rules()[3].conditions;
    m->add(domain, std::move(r));
  }
  return m;
}

const RuleMatcher& cached(bool worst, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<RuleMatcher>> cache;
  auto& slot = cache[{worst, n}];
  if (!slot) slot = worst ? one_bucket(n) : realistic(n);
  return *slot;
}

struct Query {
  State state;
  Goal goal;
  ObjectId fork = 0;
  Action expected;
};

const Query& fork_query() {
  static const Query query = [] {
    const World& w = kitchen().world;
    Query q;
    q.state = w.state;
    for (const char* a : {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)",
                          "(put-in ceramic-plate1 dishwasher1)", "(close dishwasher1)"})
      q.state = apply(*w.domain, q.state, parse(w, a));
    q.goal = parse_goal_or_die(w, "(and (in metal-fork1 dishwasher1) (closed dishwasher1))");
    q.fork = *w.universe->find("metal-fork1");
    q.expected = parse(w, "(open dishwasher1)");
    return q;
  }();
  return query;
}

// How many rules the query's buckets hold (what select has to try), by
// the matcher's indexing rule: same goal shape, a goal category of none or
// one of the goal's objects', a subtask test of none or "clear".
std::size_t rules_read(const RuleMatcher& m, const Query& q) {
  const World& w = kitchen().world;
  std::set<std::string> categories;
  for (ObjectId o : q.goal.objects()) categories.insert(w.universe->info(o).category);
  std::multiset<std::pair<PredicateId, bool>> shape;
  for (const Literal& l : q.goal.literals) shape.emplace(l.fact.predicate, l.positive);
  std::size_t read = 0;
  for (const Rule& r : m.rules()) {
    std::multiset<std::pair<PredicateId, bool>> rule_shape;
    for (const LiteralPattern& l : r.goal) rule_shape.emplace(l.atom.predicate, l.positive);
    if (rule_shape != shape) continue;
    if (r.subtask && *r.subtask != "clear") continue;
    std::optional<std::string> category;
    for (const LiteralPattern& l : r.goal)
      for (std::uint8_t i = 0; i < l.atom.arity && !category; ++i) category = r.variables[l.atom.args[i]].category;
    if (category && !categories.count(*category)) continue;
    ++read;
  }
  return read;
}

void run(benchmark::State& state, bool worst) {
  const World& w = kitchen().world;
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const RuleMatcher& m = cached(worst, n);
  const Query& q = fork_query();
  MatchQuery query{&q.state, &q.goal, q.fork, "clear"};
  auto selected = m.select(*w.domain, *w.universe, query);
  if (!worst && (!selected || selected->action != q.expected)) {
    state.SkipWithError("select did not propose (open dishwasher1)");
    return;
  }
  for (auto _ : state) {
    auto s = m.select(*w.domain, *w.universe, query);
    benchmark::DoNotOptimize(s);
  }
  state.counters["rules"] = static_cast<double>(m.size());
  state.counters["read"] = static_cast<double>(rules_read(m, q));
}

void BM_SelectRealistic(benchmark::State& state) { run(state, false); }
void BM_SelectOneBucket(benchmark::State& state) { run(state, true); }

BENCHMARK(BM_SelectRealistic)->Arg(10)->Arg(1000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SelectOneBucket)->Arg(10)->Arg(1000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace apprentice

BENCHMARK_MAIN();
