// State is a value: equal facts make equal states (whatever the order or
// duplicates they were built from), equal states hash alike, copies share
// their storage, and "changing" a state makes a new one. The large-state
// tests cross the B+tree's leaf (64 facts) and inner-node (32 children)
// limits, so that splits, merges and a tree of several levels are exercised,
// and compare State with a plain std::set<Fact>.
#include "world/state.h"
#include "world/state_lookup.h"

#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <type_traits>
#include <unordered_set>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace apprentice {
namespace {

constexpr PredicateId kOn = 0;
constexpr PredicateId kClosed = 1;
constexpr PredicateId kHandempty = 2;

std::vector<Fact> some_facts() {
  return {Fact(kOn, {4, 1}), Fact(kClosed, {2}), Fact(kHandempty, std::initializer_list<ObjectId>{}),
          Fact(kOn, {5, 1}), Fact(kClosed, {3})};
}

TEST(Fact, UnusedArgumentSlotsDoNotBreakEquality) {
  Fact a(kClosed, {2});
  Fact b;
  b.predicate = kClosed;
  b.arity = 1;
  b.args[0] = 2;
  EXPECT_EQ(a, b);
  EXPECT_EQ(hash_value(a), hash_value(b));
  EXPECT_NE(Fact(kOn, {1, 2}), Fact(kOn, {2, 1}));
  EXPECT_TRUE(Fact(kOn, {1, 2}).mentions(2));
  EXPECT_FALSE(Fact(kOn, {1, 2}).mentions(3));
}

TEST(State, IsARegularValueType) {
  static_assert(std::is_copy_constructible_v<State>);
  static_assert(std::is_copy_assignable_v<State>);
  static_assert(std::is_nothrow_move_constructible_v<State>);
  static_assert(std::is_default_constructible_v<State>);
  // Copying a state copies two pointers (the tree and its index by second
  // argument), the size and the hash, nothing more.
  static_assert(sizeof(State) <= 6 * sizeof(void*));
}

TEST(State, DefaultIsEmpty) {
  State empty;
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_EQ(empty, State(std::vector<Fact>{}));
  EXPECT_EQ(empty.hash(), State(std::vector<Fact>{}).hash());
  EXPECT_FALSE(empty.holds(Fact(kClosed, {2})));
}

TEST(State, ConstructionIgnoresOrderAndDuplicates) {
  std::vector<Fact> facts = some_facts();
  State reference(facts);
  std::mt19937 rng(7);
  for (int round = 0; round < 20; ++round) {
    std::vector<Fact> shuffled = facts;
    shuffled.insert(shuffled.end(), facts.begin(), facts.begin() + round % facts.size());
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    State other(shuffled);
    EXPECT_EQ(other, reference);
    EXPECT_FALSE(other < reference);
    EXPECT_FALSE(reference < other);
    EXPECT_EQ(other.hash(), reference.hash());
    EXPECT_EQ(other.size(), facts.size());
  }
}

TEST(State, FactsAreSortedAndUnique) {
  std::vector<Fact> facts = some_facts();
  facts.push_back(facts.front());
  State state(facts);
  auto view = state.facts();
  EXPECT_TRUE(std::is_sorted(view.begin(), view.end()));
  EXPECT_EQ(std::adjacent_find(view.begin(), view.end()), view.end());
  EXPECT_EQ(view.size(), 5u);
}

TEST(State, HoldsAndSatisfies) {
  State state(some_facts());
  EXPECT_TRUE(state.holds(Fact(kClosed, {2})));
  EXPECT_FALSE(state.holds(Fact(kClosed, {4})));
  EXPECT_TRUE(state.satisfies(Literal{Fact(kClosed, {2}), true}));
  EXPECT_FALSE(state.satisfies(Literal{Fact(kClosed, {2}), false}));
  EXPECT_TRUE(state.satisfies(Literal{Fact(kClosed, {4}), false}));
}

TEST(State, DifferentFactsMakeDifferentStates) {
  State a(some_facts());
  std::vector<Fact> fewer = some_facts();
  fewer.pop_back();
  State b(fewer);
  EXPECT_NE(a, b);
  EXPECT_TRUE(a < b || b < a);
  EXPECT_NE(a, State());
}

TEST(State, LessThanIsAStrictTotalOrder) {
  std::vector<State> states;
  std::vector<Fact> pool = some_facts();
  for (unsigned mask = 0; mask < (1u << pool.size()); ++mask) {
    std::vector<Fact> chosen;
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (mask & (1u << i)) chosen.push_back(pool[i]);
    states.emplace_back(chosen);
  }
  std::set<State> ordered(states.begin(), states.end());
  EXPECT_EQ(ordered.size(), states.size());
  for (const State& a : states)
    for (const State& b : states) {
      EXPECT_EQ(a == b, !(a < b) && !(b < a));
      EXPECT_FALSE(a < b && b < a);
    }
}

TEST(State, WorksAsAHashSetKey) {
  std::unordered_set<State, StateHash> seen;
  std::vector<Fact> facts = some_facts();
  seen.insert(State(facts));
  std::reverse(facts.begin(), facts.end());
  EXPECT_FALSE(seen.insert(State(facts)).second);
  facts.pop_back();
  EXPECT_TRUE(seen.insert(State(facts)).second);
  EXPECT_EQ(seen.size(), 2u);
}

TEST(State, CopiesShareStorage) {
  State a(some_facts());
  State b = a;
  EXPECT_TRUE(a.shares_root_with(b));
  State c;
  c = b;
  EXPECT_TRUE(c.shares_root_with(a));
  EXPECT_EQ(c, a);
  EXPECT_EQ(c.hash(), a.hash());
}

TEST(State, WithChangesMakesANewStateAndLeavesTheOldOne) {
  State before(some_facts());
  const Fact opened(kClosed, {2});
  const Fact held(kOn, {7, 1});
  State after = before.with_changes(std::vector<Fact>{opened}, std::vector<Fact>{held});
  EXPECT_TRUE(before.holds(opened));
  EXPECT_FALSE(before.holds(held));
  EXPECT_FALSE(after.holds(opened));
  EXPECT_TRUE(after.holds(held));
  EXPECT_EQ(after.size(), before.size());
  EXPECT_NE(after, before);

  // The same change built another way is the same value.
  std::vector<Fact> expected = some_facts();
  expected.erase(std::find(expected.begin(), expected.end(), opened));
  expected.push_back(held);
  EXPECT_EQ(after, State(expected));
  EXPECT_EQ(after.hash(), State(expected).hash());
}

TEST(State, WithChangesAddWinsOverDeleteAndIgnoresAbsentFacts) {
  State before(some_facts());
  const Fact f(kClosed, {9});
  // Deleting a fact that is not there changes nothing.
  EXPECT_EQ(before.with_changes(std::vector<Fact>{f}, {}), before);
  // A fact both deleted and added ends up present (adds apply after deletes).
  const Fact g(kClosed, {2});
  State after = before.with_changes(std::vector<Fact>{g}, std::vector<Fact>{g});
  EXPECT_TRUE(after.holds(g));
  EXPECT_EQ(after, before);
  // Adding a fact already there keeps the state equal.
  EXPECT_EQ(before.with_changes({}, std::vector<Fact>{g}), before);
}

TEST(State, UndoingAChangeGivesBackAnEqualState) {
  State start(some_facts());
  const Fact a(kClosed, {2});
  const Fact b(kOn, {8, 1});
  State changed = start.with_changes(std::vector<Fact>{a}, std::vector<Fact>{b});
  State back = changed.with_changes(std::vector<Fact>{b}, std::vector<Fact>{a});
  EXPECT_EQ(back, start);
  EXPECT_EQ(back.hash(), start.hash());
  EXPECT_FALSE(back.shares_root_with(start));
}

// Random facts over a few predicates and objects, with duplicates.
std::vector<Fact> random_facts(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> predicate(0, 3), object(0, 9), arity(0, 3);
  std::vector<Fact> facts;
  for (int i = 0; i < n; ++i) {
    std::vector<ObjectId> args;
    for (int a = arity(rng); a > 0; --a) args.push_back(static_cast<ObjectId>(object(rng)));
    facts.emplace_back(static_cast<PredicateId>(predicate(rng)), std::span<const ObjectId>(args));
  }
  return facts;
}

TEST(State, WithChangesAgreesWithRemovingThenAddingOneByOne) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<Fact> start = random_facts(rng, 40);
    const std::vector<Fact> removed = random_facts(rng, 15);
    const std::vector<Fact> added = random_facts(rng, 15);
    std::set<Fact> expected(start.begin(), start.end());
    for (const Fact& f : removed) expected.erase(f);
    expected.insert(added.begin(), added.end());
    State after = State(start).with_changes(removed, added);
    EXPECT_EQ(after, State(std::vector<Fact>(expected.begin(), expected.end())));
    EXPECT_TRUE(std::equal(after.facts().begin(), after.facts().end(), expected.begin(), expected.end()));
    EXPECT_EQ(after.hash(), State(std::vector<Fact>(expected.begin(), expected.end())).hash());
  }
}

TEST(State, FactsAboutFindsExactlyThePairsWithThatFirstArgument) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 300; ++trial) {
    const State state(random_facts(rng, 60));
    for (PredicateId p = 0; p < 4; ++p) {
      for (ObjectId first = 0; first < 10; ++first) {
        std::vector<Fact> expected;
        for (const Fact& f : state.facts())
          if (f.predicate == p && f.arity == 2 && f.args[0] == first) expected.push_back(f);
        const auto found = facts_about(state, p, first);
        EXPECT_TRUE(std::equal(found.begin(), found.end(), expected.begin(), expected.end()))
            << "predicate " << p << ", first argument " << first;
      }
    }
  }
}


// ---- Large states: the B+tree against a std::set<Fact> model ----

// Facts over 3 predicates, arities 1-3 and `objects` objects.
Fact random_fact(std::mt19937& rng, ObjectId objects) {
  std::uniform_int_distribution<int> predicate(0, 2), arity(1, 3);
  std::uniform_int_distribution<ObjectId> object(0, objects - 1);
  const int a = arity(rng);
  std::vector<ObjectId> args;
  for (int i = 0; i < a; ++i) args.push_back(object(rng));
  return Fact(static_cast<PredicateId>(predicate(rng)), std::span<const ObjectId>(args));
}

std::vector<Fact> sorted(const std::set<Fact>& model) { return {model.begin(), model.end()}; }

std::vector<Fact> listed(const FactRange& range) { return {range.begin(), range.end()}; }

// The model's facts of f's predicate and arity whose second argument is
// f's, by first then third argument.
std::vector<Fact> with_second(const std::set<Fact>& model, const Fact& f) {
  std::vector<Fact> out;
  for (const Fact& m : model)
    if (m.predicate == f.predicate && m.arity == f.arity && m.args[1] == f.args[1]) out.push_back(m);
  return out;  // the set's order already sorts them by first, then third argument
}

// Checks everything State promises against the model.
void expect_matches(const State& state, const std::set<Fact>& model, std::mt19937& rng, ObjectId objects) {
  ASSERT_EQ(state.size(), model.size());
  ASSERT_EQ(listed(state.facts()), sorted(model));
  const State rebuilt(sorted(model));
  EXPECT_EQ(state, rebuilt);
  EXPECT_EQ(rebuilt, state);
  EXPECT_EQ(state.hash(), rebuilt.hash());
  EXPECT_FALSE(state < rebuilt);
  EXPECT_FALSE(rebuilt < state);
  for (int probe = 0; probe < 50; ++probe) {
    const Fact f = random_fact(rng, objects);
    EXPECT_EQ(state.holds(f), model.count(f) == 1);
    std::vector<Fact> expected;
    for (const Fact& m : model)
      if (m.predicate == f.predicate && m.arity == f.arity && m.args[0] == f.args[0]) expected.push_back(m);
    EXPECT_EQ(listed(state.facts_of(f.predicate, f.arity, f.args[0])), expected);
    if (f.arity >= 2) {
      expected = with_second(model, f);
      EXPECT_EQ(listed(state.facts_with_second(f.predicate, f.arity, f.args[1])), expected);
    }
    if (probe < 3) {
      expected.clear();
      for (const Fact& m : model)
        if (m.predicate == f.predicate) expected.push_back(m);
      EXPECT_EQ(listed(state.facts_of(f.predicate)), expected);
    }
  }
}

TEST(LargeState, WithChangesAgreesWithASetOverManyRounds) {
  std::mt19937 rng(21);
  constexpr ObjectId kObjects = 60;
  std::set<Fact> model;
  std::vector<Fact> start;
  for (int i = 0; i < 5000; ++i) start.push_back(random_fact(rng, kObjects));
  model.insert(start.begin(), start.end());
  State state(start);
  expect_matches(state, model, rng, kObjects);
  for (int round = 0; round < 200; ++round) {
    // Mostly small changes, as actions make; now and then a large one that
    // splits or empties whole leaves.
    const int size = round % 25 == 0 ? 3000 : 4;
    std::vector<Fact> removed, added;
    for (int i = 0; i < size; ++i) {
      // Removals mostly of facts that hold, so that the state shrinks too.
      if (!model.empty() && i % 2 == 0) {
        auto it = model.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, model.size() - 1)(rng));
        removed.push_back(*it);
      } else {
        removed.push_back(random_fact(rng, kObjects));
      }
      added.push_back(random_fact(rng, kObjects));
    }
    if (round % 50 == 49) added.clear();  // only removals
    const State before = state;
    const std::vector<Fact> before_facts = listed(before.facts());
    state = state.with_changes(removed, added);
    for (const Fact& f : removed) model.erase(f);
    model.insert(added.begin(), added.end());
    ASSERT_EQ(listed(before.facts()), before_facts) << "with_changes changed the old state";
    if (round % 10 == 0 || size > 4) expect_matches(state, model, rng, kObjects);
    else ASSERT_EQ(listed(state.facts()), sorted(model));
  }
  expect_matches(state, model, rng, kObjects);
}

TEST(LargeState, RemovingEverythingGivesTheEmptyState) {
  std::mt19937 rng(22);
  std::vector<Fact> facts;
  for (int i = 0; i < 20000; ++i) facts.push_back(random_fact(rng, 100));
  const State full(facts);
  // Remove in three batches, from the middle outwards.
  std::vector<Fact> all = listed(full.facts());
  const std::size_t third = all.size() / 3;
  State state = full.with_changes(std::span<const Fact>(all).subspan(third, third), {});
  state = state.with_changes(std::span<const Fact>(all).first(third), {});
  EXPECT_EQ(state.size(), all.size() - 2 * third);
  state = state.with_changes(std::span<const Fact>(all).subspan(2 * third), {});
  EXPECT_EQ(state.size(), 0u);
  EXPECT_EQ(state, State());
  EXPECT_EQ(state.hash(), State().hash());
  EXPECT_TRUE(state.facts().empty());
  // And growing it back one fact at a time gives the bulk-built state.
  std::shuffle(all.begin(), all.end(), rng);
  for (const Fact& f : all) state = state.with_changes({}, std::span<const Fact>(&f, 1));
  EXPECT_EQ(state, full);
  EXPECT_EQ(state.hash(), full.hash());
  EXPECT_EQ(listed(state.facts()), listed(full.facts()));
}

TEST(LargeState, DifferentChangeOrdersGiveEqualStatesAndHashes) {
  std::mt19937 rng(23);
  std::vector<Fact> base;
  for (int i = 0; i < 10000; ++i) base.push_back(random_fact(rng, 200));
  const State start(base);
  std::vector<std::pair<Fact, Fact>> moves;  // (removed, added)
  for (int i = 0; i < 400; ++i) moves.emplace_back(base[static_cast<std::size_t>(i) * 7], random_fact(rng, 200));
  // Order 1: one move at a time, in order. Order 2: in reverse, in pairs.
  // (Each added fact is distinct from every removed one in the batch only
  // by chance, so compare against the model built the same way.)
  std::set<Fact> model(base.begin(), base.end());
  for (const auto& [r, a] : moves) model.erase(r);
  for (const auto& [r, a] : moves) model.insert(a);
  std::vector<Fact> removed, added;
  for (const auto& [r, a] : moves) removed.push_back(r), added.push_back(a);
  const State all_at_once = start.with_changes(removed, added);
  State removals_first = start;
  for (const auto& [r, a] : moves) removals_first = removals_first.with_changes(std::span<const Fact>(&r, 1), {});
  for (auto it = moves.rbegin(); it != moves.rend(); ++it)
    removals_first = removals_first.with_changes({}, std::span<const Fact>(&it->second, 1));
  const State bulk(sorted(model));
  EXPECT_EQ(all_at_once, bulk);
  EXPECT_EQ(removals_first, bulk);
  EXPECT_EQ(all_at_once, removals_first);
  EXPECT_EQ(all_at_once.hash(), bulk.hash());
  EXPECT_EQ(removals_first.hash(), bulk.hash());
  EXPECT_FALSE(all_at_once < removals_first);
  EXPECT_FALSE(removals_first < all_at_once);
  // One more fact makes them differ, and ordering agrees with the sorted
  // sequences.
  const Fact extra(7, {1, 2});
  const State more = bulk.with_changes({}, std::span<const Fact>(&extra, 1));
  EXPECT_NE(more, all_at_once);
  EXPECT_NE(more.hash(), all_at_once.hash());
  const std::vector<Fact> a = listed(more.facts()), b = listed(all_at_once.facts());
  EXPECT_EQ(more < all_at_once, std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end()));
  EXPECT_EQ(all_at_once < more, std::lexicographical_compare(b.begin(), b.end(), a.begin(), a.end()));
}

TEST(LargeState, ChangesThatChangeNothingKeepTheSameTree) {
  std::mt19937 rng(24);
  std::vector<Fact> facts;
  for (int i = 0; i < 3000; ++i) facts.push_back(random_fact(rng, 50));
  const State state(facts);
  const Fact absent(9, {1});
  EXPECT_TRUE(state.with_changes(std::span<const Fact>(&absent, 1), {}).shares_root_with(state));
  EXPECT_TRUE(state.with_changes({}, std::span<const Fact>(&facts[5], 1)).shares_root_with(state));
}

TEST(LargeState, RangeQueriesAtTheEdgesOfIds) {
  const ObjectId top = std::numeric_limits<ObjectId>::max();
  const PredicateId last = std::numeric_limits<PredicateId>::max();
  std::vector<Fact> facts;
  for (ObjectId i = 0; i < 500; ++i) facts.push_back(Fact(3, {top, i}));
  for (ObjectId i = 0; i < 500; ++i) facts.push_back(Fact(3, {top - 1, i}));
  facts.push_back(Fact(3, {0, 0, 0}));
  facts.push_back(Fact(last, {top}));
  facts.push_back(Fact(last, {0, top}));
  const State state(facts);
  EXPECT_EQ(state.facts_of(3, 2, top).size(), 500u);
  EXPECT_EQ(state.facts_of(3, 2, top - 1).size(), 500u);
  EXPECT_EQ(state.facts_of(3, 3, 0).size(), 1u);
  EXPECT_EQ(state.facts_of(3).size(), 1001u);
  EXPECT_EQ(state.facts_of(last).size(), 2u);
  EXPECT_EQ(state.facts_of(last, 1, top).size(), 1u);
  EXPECT_TRUE(state.facts_of(4).empty());
  EXPECT_TRUE(state.facts_between(Fact(3, {top}), Fact(3, {0})).empty());  // an empty interval
  EXPECT_EQ(state.facts_of(3, 2, top).front(), Fact(3, {top, 0}));
  EXPECT_EQ(state.facts_with_second(3, 2, 7).size(), 2u);
  EXPECT_EQ(state.facts_with_second(3, 2, 7).front(), Fact(3, {top - 1, 7}));
  EXPECT_EQ(state.facts_with_second(last, 2, top).size(), 1u);
  EXPECT_TRUE(state.facts_with_second(3, 3, 1).empty());
}

TEST(LargeState, ARangeOutlivesItsState) {
  FactRange range;
  {
    std::vector<Fact> facts;
    for (ObjectId i = 0; i < 1000; ++i) facts.push_back(Fact(1, {i}));
    range = State(facts).facts_of(1);
  }
  EXPECT_EQ(range.size(), 1000u);
  EXPECT_EQ(range.front(), Fact(1, {0}));
}

// Property: any sequence of with_changes on a State agrees with the same
// changes on a std::set<Fact>, whatever the sizes (small enough for one
// leaf or large enough for three levels).
RC_GTEST_PROP(StateModel, AgreesWithAStdSet, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  const auto objects = *rc::gen::inRange<ObjectId>(1, 400);
  const auto start_size = *rc::gen::inRange(0, 6000);
  const auto steps = *rc::gen::inRange(1, 12);
  std::mt19937 rng(seed);
  std::vector<Fact> start;
  for (int i = 0; i < start_size; ++i) start.push_back(random_fact(rng, objects));
  std::set<Fact> model(start.begin(), start.end());
  State state(start);
  for (int step = 0; step < steps; ++step) {
    const auto removing = *rc::gen::inRange(0, 2000);
    const auto adding = *rc::gen::inRange(0, 2000);
    std::vector<Fact> removed, added;
    for (int i = 0; i < removing; ++i) {
      if (!model.empty() && i % 3 != 0) {
        auto it = model.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, model.size() - 1)(rng) % 64);
        removed.push_back(*it);
      }
      removed.push_back(random_fact(rng, objects));
    }
    for (int i = 0; i < adding; ++i) added.push_back(random_fact(rng, objects));
    state = state.with_changes(removed, added);
    for (const Fact& f : removed) model.erase(f);
    model.insert(added.begin(), added.end());
    RC_ASSERT(state.size() == model.size());
    RC_ASSERT(listed(state.facts()) == sorted(model));
    const State rebuilt(sorted(model));
    RC_ASSERT(state == rebuilt);
    RC_ASSERT(state.hash() == rebuilt.hash());
    const Fact probe = random_fact(rng, objects);
    RC_ASSERT(state.holds(probe) == (model.count(probe) == 1));
    std::vector<Fact> about;
    for (const Fact& m : model)
      if (m.predicate == probe.predicate && m.arity == probe.arity && m.args[0] == probe.args[0]) about.push_back(m);
    RC_ASSERT(listed(state.facts_of(probe.predicate, probe.arity, probe.args[0])) == about);
    if (probe.arity >= 2)
      RC_ASSERT(listed(state.facts_with_second(probe.predicate, probe.arity, probe.args[1])) ==
                with_second(model, probe));
  }
}

}  // namespace
}  // namespace apprentice
