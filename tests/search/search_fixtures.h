// Helpers for the search tests: the kitchen domain, generated small
// kitchens, and an independent breadth-first search that serves as the
// reference for optimality. Paths and scenarios come from tests/common.
#pragma once

#include <cstdlib>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/scenarios.h"
#include "search/iterative_deepening.h"
#include "world/action.h"
#include "world/pddl.h"
#include "world/scenario.h"
#include "world/simulator.h"
#include "world/vocabulary.h"

namespace apprentice::testing {

inline Scenario tidy_kitchen() { return shipped_scenario("tidy-kitchen"); }

// A domain file of data/domains, read once.
inline std::shared_ptr<const Domain> shipped_domain(const std::string& relative) {
  static std::map<std::string, std::shared_ptr<const Domain>> cache;
  auto& slot = cache[relative];
  if (!slot) {
    auto domain = read_domain_file(source_path(relative));
    if (!domain) {
      ADD_FAILURE() << domain.error().describe();
      std::abort();
    }
    slot = std::make_shared<const Domain>(std::move(*domain));
  }
  return slot;
}

inline std::shared_ptr<const Domain> kitchen_domain() { return shipped_domain("data/domains/kitchen.pddl"); }

inline Goal goal_or_die(const World& world, std::string_view text) {
  auto goal = parse_goal(*world.domain, *world.universe, text);
  if (!goal) {
    ADD_FAILURE() << goal.error().describe();
    std::abort();
  }
  return std::move(*goal);
}

inline std::vector<std::string> plan_text(const World& world, const std::vector<Action>& plan) {
  std::vector<std::string> out;
  for (const Action& a : plan) out.push_back(format_action(*world.domain, *world.universe, a));
  return out;
}

// Replays a plan in the simulator; true if every step is accepted and the
// goal holds at the end (a refused step is also reported as a failure).
inline bool plan_reaches(const World& world, const std::vector<Action>& plan, const Goal& goal) {
  Simulator sim(world);
  for (const Action& a : plan) {
    Status status = sim.execute(a);
    if (!status) {
      ADD_FAILURE() << status.error().describe();
      return false;
    }
  }
  return goal.satisfied_by(sim.state());
}

// A small kitchen described by plain numbers, so that RapidCheck can
// generate and shrink it. Places come first; every place of kind
// receptacle may have a door.
struct PlaceSpec {
  bool surface = true;
  bool door = false;    // receptacles only
  bool closed = false;  // doors only
};

struct GoalSpec {
  int item = 0;   // index into items
  int place = 0;  // index into places
  // 0: no door literal; 1: (closed r); 2: (not (closed r)), for r = door_place.
  int door_literal = 0;
  int door_place = 0;
  // A second placement, for another item, when second_item >= 0.
  int second_item = -1;
  int second_place = 0;
};

struct WorldSpec {
  std::vector<PlaceSpec> places;
  // For each item, the index of the place it starts at, or -1 for in hand
  // (at most one item is in hand).
  std::vector<int> item_at;
  GoalSpec goal;
};

inline void print_places(std::ostream& os, const std::vector<PlaceSpec>& places) {
  os << "places:";
  for (std::size_t i = 0; i < places.size(); ++i) {
    const PlaceSpec& p = places[i];
    os << " p" << i << "=" << (p.surface ? "surface" : "receptacle");
    if (p.door) os << (p.closed ? "[closed]" : "[open]");
  }
}

inline void print_goal(std::ostream& os, const GoalSpec& goal) {
  os << "; goal: i" << goal.item << " at p" << goal.place;
  if (goal.second_item >= 0) os << ", i" << goal.second_item << " at p" << goal.second_place;
  if (goal.door_literal == 1) os << ", p" << goal.door_place << " closed";
  if (goal.door_literal == 2) os << ", p" << goal.door_place << " open";
}

inline std::ostream& operator<<(std::ostream& os, const WorldSpec& spec) {
  print_places(os, spec.places);
  os << "; items:";
  for (std::size_t i = 0; i < spec.item_at.size(); ++i)
    os << " i" << i << "@" << (spec.item_at[i] < 0 ? std::string("hand") : "p" + std::to_string(spec.item_at[i]));
  print_goal(os, spec.goal);
  return os;
}

// A generated problem: a world (for the Simulator) and a goal.
struct Problem {
  World world;
  Goal goal;
};

inline Problem build_problem(const WorldSpec& spec) {
  std::shared_ptr<const Domain> domain = kitchen_domain();
  auto vocabulary = Vocabulary::resolve(*domain);
  if (!vocabulary) std::abort();
  const Vocabulary& v = *vocabulary;
  Universe universe;
  std::vector<Fact> facts;
  std::vector<ObjectId> places, items;
  for (std::size_t i = 0; i < spec.places.size(); ++i) {
    const PlaceSpec& p = spec.places[i];
    std::string category = p.surface ? "shelf" : (p.door ? "cabinet" : "bin");
    ObjectKind kind = p.surface ? ObjectKind::kSurface : ObjectKind::kReceptacle;
    ObjectId id = universe.add(ObjectInfo{category + std::to_string(i), category, kind,
                                          *domain->find_type(type_name(kind)), {}});
    places.push_back(id);
    facts.push_back(Fact(p.surface ? v.surface : v.receptacle, {id}));
    if (!p.surface && p.door) {
      facts.push_back(Fact(v.openable, {id}));
      if (p.closed) facts.push_back(Fact(v.closed, {id}));
    }
  }
  bool hand_full = false;
  for (std::size_t i = 0; i < spec.item_at.size(); ++i) {
    ObjectId id = universe.add(ObjectInfo{"thing" + std::to_string(i), "thing", ObjectKind::kItem,
                                          *domain->find_type("item"), {}});
    items.push_back(id);
    facts.push_back(Fact(v.grabbable, {id}));
    int at = spec.item_at[i];
    if (at < 0) {
      facts.push_back(Fact(v.holding, {id}));
      hand_full = true;
    } else {
      ObjectId place = places.at(static_cast<std::size_t>(at));
      facts.push_back(Fact(spec.places[static_cast<std::size_t>(at)].surface ? v.on : v.in, {id, place}));
    }
  }
  if (!hand_full) facts.push_back(Fact(v.handempty, std::initializer_list<ObjectId>{}));

  std::vector<Literal> literals;
  const GoalSpec& g = spec.goal;
  ObjectId goal_place = places.at(static_cast<std::size_t>(g.place));
  literals.push_back(Literal{
      Fact(spec.places[static_cast<std::size_t>(g.place)].surface ? v.on : v.in,
           {items.at(static_cast<std::size_t>(g.item)), goal_place}),
      true});
  if (g.second_item >= 0) {
    const auto place = static_cast<std::size_t>(g.second_place);
    literals.push_back(Literal{
        Fact(spec.places[place].surface ? v.on : v.in, {items.at(static_cast<std::size_t>(g.second_item)), places.at(place)}),
        true});
  }
  if (g.door_literal != 0 && !spec.places[static_cast<std::size_t>(g.door_place)].surface)
    literals.push_back(Literal{Fact(v.closed, {places.at(static_cast<std::size_t>(g.door_place))}), g.door_literal == 1});

  Problem problem;
  problem.world.domain = domain;
  problem.world.vocabulary = v;
  problem.world.universe = std::make_shared<const Universe>(std::move(universe));
  problem.world.state = State(std::move(facts));
  problem.world.location = "kitchen";
  problem.goal = Goal(std::move(literals));
  return problem;
}

// Breadth-first search over every well-typed argument tuple of every
// schema, with its own applicability check and successor function (only
// the instantiation of preconditions and effects is shared with the code
// under test). Returns the length of a shortest plan, or nullopt if the
// goal is unreachable. Exhaustive: meant for small worlds only.
inline std::optional<int> shortest_plan_length(const Domain& domain, const Universe& universe, const State& initial,
                                               const Goal& goal) {
  std::vector<Action> actions;
  for (std::size_t s = 0; s < domain.actions.size(); ++s) {
    const ActionSchema& schema = domain.actions[s];
    const std::size_t n = schema.parameters.size();
    std::vector<ObjectId> args(n, 0);
    const std::size_t objects = universe.size();
    if (n > 0 && objects == 0) continue;
    for (;;) {
      bool typed = true;
      for (std::size_t p = 0; p < n; ++p)
        if (!domain.is_subtype(universe.info(args[p]).type, schema.parameters[p].type)) typed = false;
      bool equalities = true;
      for (const EqualitySchema& e : schema.equalities)
        if ((args[e.left] == args[e.right]) != e.positive) equalities = false;
      if (typed && equalities) actions.emplace_back(static_cast<ActionSchemaId>(s), args);
      std::size_t p = 0;
      while (p < n && ++args[p] == objects) args[p++] = 0;
      if (p == n) break;
    }
  }
  auto applicable = [&](const State& state, const Action& action) {
    for (const Literal& l : preconditions_of(domain, action))
      if (state.holds(l.fact) != l.positive) return false;
    return true;
  };
  auto successor = [&](const State& state, const Action& action) {
    std::vector<Fact> facts;
    std::vector<Fact> removed = delete_effects_of(domain, action);
    for (const Fact& f : state.facts())
      if (std::find(removed.begin(), removed.end(), f) == removed.end()) facts.push_back(f);
    for (const Fact& f : add_effects_of(domain, action)) facts.push_back(f);
    return State(std::move(facts));
  };

  std::unordered_map<State, int, StateHash> distance;
  std::deque<State> queue;
  distance.emplace(initial, 0);
  queue.push_back(initial);
  while (!queue.empty()) {
    State state = queue.front();
    queue.pop_front();
    int d = distance.at(state);
    if (goal.satisfied_by(state)) return d;
    for (const Action& action : actions) {
      if (!applicable(state, action)) continue;
      State next = successor(state, action);
      if (distance.emplace(next, d + 1).second) queue.push_back(std::move(next));
    }
  }
  return std::nullopt;
}

}  // namespace apprentice::testing
