// RapidCheck generators of small planning problems for the property tests:
// small kitchens (search_fixtures.h's WorldSpec) and small kitchens with
// stacking dishes (data/domains/kitchen-stacking.pddl), where objects
// interact.
#pragma once

#include <rapidcheck.h>

#include "search_fixtures.h"

namespace apprentice::testing {

// Sizes are fixed at RapidCheck's nominal size so that the choices below
// are spread over their whole ranges from the first test on (shrinking
// still makes counterexamples small).
inline rc::Gen<WorldSpec> small_worlds() {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([] {
    WorldSpec spec;
    const int places = *rc::gen::inRange(1, 7);
    for (int i = 0; i < places; ++i) {
      PlaceSpec p;
      p.surface = *rc::gen::arbitrary<bool>();
      if (!p.surface) {
        p.door = *rc::gen::arbitrary<bool>();
        if (p.door) p.closed = *rc::gen::arbitrary<bool>();
      }
      spec.places.push_back(p);
    }
    const int items = *rc::gen::inRange(1, 4);
    const int held = *rc::gen::inRange(-1, items);  // -1: the hand is empty
    for (int i = 0; i < items; ++i) spec.item_at.push_back(i == held ? -1 : *rc::gen::inRange(0, places));
    spec.goal.item = *rc::gen::inRange(0, items);
    // Mostly somewhere the item is not yet, so that most goals need a plan.
    const int start = spec.item_at[static_cast<std::size_t>(spec.goal.item)];
    spec.goal.place = (places > 1 && start >= 0 && *rc::gen::inRange(0, 4) != 0)
                          ? (start + *rc::gen::inRange(1, places)) % places
                          : *rc::gen::inRange(0, places);
    spec.goal.door_literal = *rc::gen::inRange(0, 3);
    spec.goal.door_place = *rc::gen::inRange(0, places);
    if (items > 1 && *rc::gen::inRange(0, 3) == 0) {
      spec.goal.second_item = (spec.goal.item + *rc::gen::inRange(1, items)) % items;
      spec.goal.second_place = *rc::gen::inRange(0, places);
    }
    return spec;
  }));
}


// A small kitchen where dishes stack. Places: surfaces first, then
// receptacles. Items stand on a place; on a surface an item may rest on an
// uncovered earlier item of the same surface (both stackable), which makes
// towers. The goal puts one or two items somewhere, maybe with a door
// literal.
struct StackWorldSpec {
  std::vector<PlaceSpec> places;
  std::vector<int> item_at;     // place index
  std::vector<int> item_on;     // index of the item it rests on, or -1
  std::vector<bool> stackable;
  GoalSpec goal;
};

inline std::ostream& operator<<(std::ostream& os, const StackWorldSpec& spec) {
  print_places(os, spec.places);
  os << "; items:";
  for (std::size_t i = 0; i < spec.item_at.size(); ++i) {
    os << " i" << i << "@p" << spec.item_at[i];
    if (spec.item_on[i] >= 0) os << "/on-i" << spec.item_on[i];
    if (spec.stackable[i]) os << "[s]";
  }
  print_goal(os, spec.goal);
  return os;
}

inline rc::Gen<StackWorldSpec> small_stack_worlds() {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([] {
    StackWorldSpec spec;
    const int surfaces = *rc::gen::inRange(1, 3);
    const int receptacles = *rc::gen::inRange(1, 3);
    for (int i = 0; i < surfaces; ++i) spec.places.push_back(PlaceSpec{true, false, false});
    for (int i = 0; i < receptacles; ++i) {
      PlaceSpec p{false, *rc::gen::arbitrary<bool>(), false};
      if (p.door) p.closed = *rc::gen::arbitrary<bool>();
      spec.places.push_back(p);
    }
    const int places = surfaces + receptacles;
    const int items = *rc::gen::inRange(2, 6);
    std::vector<bool> covered;
    for (int i = 0; i < items; ++i) {
      // Mostly on a surface, where stacks can form.
      const int at = *rc::gen::inRange(0, 4) != 0 ? *rc::gen::inRange(0, surfaces) : *rc::gen::inRange(0, places);
      const bool stackable = *rc::gen::inRange(0, 4) != 0;
      int on = -1;
      if (at < surfaces && stackable && *rc::gen::arbitrary<bool>()) {
        for (int j = i - 1; j >= 0; --j)
          if (spec.item_at[static_cast<std::size_t>(j)] == at && spec.stackable[static_cast<std::size_t>(j)] &&
              !covered[static_cast<std::size_t>(j)]) {
            on = j;
            break;
          }
      }
      spec.item_at.push_back(at);
      spec.item_on.push_back(on);
      spec.stackable.push_back(stackable);
      covered.push_back(false);
      if (on >= 0) covered[static_cast<std::size_t>(on)] = true;
    }
    // Mostly a covered item, so that the stack must come apart.
    int goal_item = *rc::gen::inRange(0, items);
    for (int i = 0; i < items; ++i)
      if (covered[static_cast<std::size_t>(i)] && *rc::gen::inRange(0, 3) != 0) goal_item = i;
    spec.goal.item = goal_item;
    spec.goal.place = (spec.item_at[static_cast<std::size_t>(goal_item)] + *rc::gen::inRange(1, places)) % places;
    spec.goal.door_literal = *rc::gen::inRange(0, 3);
    spec.goal.door_place = *rc::gen::inRange(0, places);
    if (*rc::gen::arbitrary<bool>()) {
      spec.goal.second_item = (spec.goal.item + *rc::gen::inRange(1, items)) % items;
      spec.goal.second_place = *rc::gen::inRange(0, places);
    }
    return spec;
  }));
}

inline std::shared_ptr<const Domain> stacking_domain() { return shipped_domain("data/domains/kitchen-stacking.pddl"); }

inline Problem build_stack_problem(const StackWorldSpec& spec) {
  std::shared_ptr<const Domain> domain = stacking_domain();
  auto vocabulary = Vocabulary::resolve(*domain);
  if (!vocabulary) std::abort();
  const Vocabulary& v = *vocabulary;
  const PredicateId stackable = domain->predicate("stackable"), stacked = domain->predicate("stacked"),
                    covered = domain->predicate("covered"), resting = domain->predicate("resting");
  Universe universe;
  std::vector<Fact> facts{Fact(v.handempty, std::initializer_list<ObjectId>{})};
  std::vector<ObjectId> places, items;
  for (std::size_t i = 0; i < spec.places.size(); ++i) {
    const PlaceSpec& p = spec.places[i];
    const ObjectKind kind = p.surface ? ObjectKind::kSurface : ObjectKind::kReceptacle;
    const std::string category = p.surface ? "shelf" : (p.door ? "cabinet" : "bin");
    ObjectId id = universe.add(ObjectInfo{category + std::to_string(i), category, kind, *domain->find_type(type_name(kind)), {}});
    places.push_back(id);
    facts.push_back(Fact(p.surface ? v.surface : v.receptacle, {id}));
    if (p.door) {
      facts.push_back(Fact(v.openable, {id}));
      if (p.closed) facts.push_back(Fact(v.closed, {id}));
    }
  }
  for (std::size_t i = 0; i < spec.item_at.size(); ++i) {
    ObjectId id = universe.add(
        ObjectInfo{"dish" + std::to_string(i), "dish", ObjectKind::kItem, *domain->find_type(type_name(ObjectKind::kItem)), {}});
    items.push_back(id);
    const auto at = static_cast<std::size_t>(spec.item_at[i]);
    facts.push_back(Fact(v.grabbable, {id}));
    facts.push_back(Fact(spec.places[at].surface ? v.on : v.in, {id, places[at]}));
    if (spec.stackable[i]) facts.push_back(Fact(stackable, {id}));
    if (spec.item_on[i] >= 0) {
      const ObjectId below = items[static_cast<std::size_t>(spec.item_on[i])];
      facts.push_back(Fact(stacked, {id, below}));
      facts.push_back(Fact(covered, {below}));
      facts.push_back(Fact(resting, {id}));
    }
  }
  std::vector<Literal> literals;
  auto placement = [&](int item, int place) {
    const auto p = static_cast<std::size_t>(place);
    return Literal{Fact(spec.places[p].surface ? v.on : v.in, {items.at(static_cast<std::size_t>(item)), places[p]}), true};
  };
  literals.push_back(placement(spec.goal.item, spec.goal.place));
  if (spec.goal.second_item >= 0) literals.push_back(placement(spec.goal.second_item, spec.goal.second_place));
  const auto door = static_cast<std::size_t>(spec.goal.door_place);
  if (spec.goal.door_literal != 0 && !spec.places[door].surface)
    literals.push_back(Literal{Fact(v.closed, {places[door]}), spec.goal.door_literal == 1});

  Problem problem;
  problem.world.domain = domain;
  problem.world.vocabulary = v;
  problem.world.universe = std::make_shared<const Universe>(std::move(universe));
  problem.world.state = State(std::move(facts));
  problem.world.location = "kitchen";
  problem.goal = Goal(std::move(literals));
  return problem;
}

}  // namespace apprentice::testing
