// State is a value: equal facts make equal states (whatever the order or
// duplicates they were built from), equal states hash alike, copies share
// their storage, and "changing" a state makes a new one.
#include "world/state.h"
#include "world/state_lookup.h"

#include <algorithm>
#include <random>
#include <set>
#include <type_traits>
#include <unordered_set>

#include <gtest/gtest.h>

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
  // Copying a state copies a pointer and a hash, nothing more.
  static_assert(sizeof(State) <= 4 * sizeof(void*));
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
  EXPECT_EQ(a.facts().data(), b.facts().data());
  State c;
  c = b;
  EXPECT_EQ(c.facts().data(), a.facts().data());
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
  EXPECT_NE(back.facts().data(), start.facts().data());
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

}  // namespace
}  // namespace apprentice
