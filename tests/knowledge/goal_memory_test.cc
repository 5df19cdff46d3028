// Declarative goal knowledge: goals are generalized into templates (the
// object of interest a variable, every other object named by its unique
// category) and instantiated for another object, in this kitchen or
// another.
#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/goal_memory.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using namespace apprentice::testing;

const GoalKey kPlateKey{"tidy kitchen", "clear", "ceramic-plate", "table"};

class GoalMemoryTest : public ::testing::Test {
 protected:
  Scenario scenario_ = tidy_kitchen();
  const World& world_ = scenario_.world;

  GoalKnowledge plate_knowledge() const {
    auto k = generalize_goal(world_, kPlateKey, object(world_, "ceramic-plate1"), goal(world_, kCeramicPlateGoal),
                             Provenance{"ceramic-plate1 (ceramic-plate)", "instructor: \"...\""});
    EXPECT_TRUE(k.has_value()) << (k ? "" : k.error().describe());
    return k ? *k : GoalKnowledge{};
  }
  std::string text(const World& world, const std::optional<Goal>& g) const {
    return g ? format_goal(*world.domain, *world.universe, *g) : "(none)";
  }
};

TEST_F(GoalMemoryTest, GeneralizeMakesTheObjectAVariableAndNamesOthersByCategory) {
  GoalKnowledge k = plate_knowledge();
  EXPECT_EQ(k.key, kPlateKey);
  ASSERT_EQ(k.literals.size(), 2u);
  EXPECT_EQ(k.literals[0], (GoalTemplateLiteral{"in", true, {{true, ""}, {false, "dishwasher"}}}));
  EXPECT_EQ(k.literals[1], (GoalTemplateLiteral{"closed", true, {{false, "dishwasher"}}}));
  EXPECT_EQ(k.provenance.object, "ceramic-plate1 (ceramic-plate)");
  EXPECT_EQ(format_goal_knowledge(k),
            "If the task is tidy kitchen, the subtask is clear and the object is a ceramic-plate at the table\n"
            "Then the goal is (in ?o dishwasher) and (closed dishwasher)\n");
}

TEST_F(GoalMemoryTest, InstantiateForAnotherObjectOfTheCategory) {
  GoalKnowledge k = plate_knowledge();
  EXPECT_EQ(text(world_, instantiate_goal(world_, k, object(world_, "ceramic-plate2"))),
            "(and (in ceramic-plate2 dishwasher1) (closed dishwasher1))");
  EXPECT_EQ(text(world_, instantiate_goal(world_, k, object(world_, "ceramic-plate1"))),
            "(and (in ceramic-plate1 dishwasher1) (closed dishwasher1))");
}

TEST_F(GoalMemoryTest, InstantiateInTheSimilarScenario) {
  GoalKnowledge k = plate_knowledge();
  Scenario similar = tidy_kitchen_similar();
  const World& w = similar.world;
  for (const char* plate : {"ceramic-plate1", "ceramic-plate2", "ceramic-plate3"})
    EXPECT_EQ(text(w, instantiate_goal(w, k, object(w, plate))),
              "(and (in " + std::string(plate) + " dishwasher1) (closed dishwasher1))");
}

TEST_F(GoalMemoryTest, EveryIntendedGoalRoundTripsToEveryObjectOfItsCategory) {
  // Learned on one object of a (subtask, category), the goal is the
  // instructor's intended goal for every other object of it, here and in
  // the similar kitchen.
  Scenario similar = tidy_kitchen_similar();
  int checked = 0;
  for (const IntentEntry& entry : scenario_.intent) {
    std::vector<ObjectId> here = world_.universe->with_category(entry.category);
    ObjectId first = 0;
    bool found = false;
    for (ObjectId o : here) {
      const Subtask* s = scenario_.subtask_of(o);
      if (s && s->verb == entry.subtask) {
        first = o;
        found = true;
        break;
      }
    }
    ASSERT_TRUE(found) << entry.subtask << " " << entry.category;
    auto intended = scenario_.intended_goal(entry.subtask, first);
    ASSERT_TRUE(intended.has_value());
    const Subtask* subtask = scenario_.subtask_of(first);
    GoalKey key{"tidy kitchen", entry.subtask, entry.category, world_.universe->info(subtask->places.front()).category};
    auto k = generalize_goal(world_, key, first, *intended, {});
    ASSERT_TRUE(k.has_value()) << k.error().describe();
    for (const Scenario* s : {&scenario_, &similar}) {
      for (ObjectId o : s->world.universe->with_category(entry.category)) {
        const Subtask* where = s->subtask_of(o);
        if (!where || where->verb != entry.subtask) continue;
        EXPECT_EQ(text(s->world, instantiate_goal(s->world, *k, o)), text(s->world, s->intended_goal(entry.subtask, o)))
            << s->name << " " << s->world.universe->name(o);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 60);
}

TEST_F(GoalMemoryTest, RefusesAGoalNamingAnObjectOfAnAmbiguousCategory) {
  // There are two ceramic plates: "the ceramic-plate" would not say which.
  Goal g = goal(world_, "(and (in metal-fork1 dishwasher1) (on ceramic-plate2 table1))");
  auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", "metal-fork", "table"},
                           object(world_, "metal-fork1"), g, {});
  ASSERT_FALSE(k.has_value());
  EXPECT_EQ(k.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(k.error().message, HasSubstr("more than one ceramic-plate"));
}

TEST_F(GoalMemoryTest, RefusesAGoalNamingOneOfTwoReceptaclesOfACategory) {
  auto two = parse_scenario(R"(
name: two-dishwashers
domain: ../domains/kitchen.pddl
places:
  - {category: table, kind: surface}
  - {category: dishwasher, kind: receptacle, door: closed}
  - {category: dishwasher, kind: receptacle, door: closed}
objects:
  - {category: ceramic-plate, at: table1}
task: {name: tidy kitchen, subtasks: [{verb: clear, place: table1}]}
intent:
  - {subtask: clear, category: ceramic-plate, receptacle: dishwasher2, closed: true}
)",
                            scenario_path("two-dishwashers"));
  ASSERT_TRUE(two.has_value()) << two.error().describe();
  const World& w = two->world;
  auto k = generalize_goal(w, kPlateKey, object(w, "ceramic-plate1"),
                           goal(w, "(and (in ceramic-plate1 dishwasher2) (closed dishwasher2))"), {});
  ASSERT_FALSE(k.has_value());
  EXPECT_THAT(k.error().message, HasSubstr("dishwasher2"));
  EXPECT_THAT(k.error().message, HasSubstr("more than one dishwasher"));
  // And a template learned where the dishwasher was unique does not guess
  // in this kitchen.
  EXPECT_FALSE(instantiate_goal(w, plate_knowledge(), object(w, "ceramic-plate1")).has_value());
}

// Look-alike places told apart by their properties (issue 10): a goal
// naming the top drawer is learned with the word that tells it apart, and
// means the top drawer wherever there is one.
TEST_F(GoalMemoryTest, PropertiesTellLookAlikePlacesApart) {
  Scenario garage = load_or_die(scenario_path("tidy-garage"));
  const World& w = garage.world;
  const GoalKey key{"tidy garage", "clear", "hammer", "workbench"};
  auto k = generalize_goal(w, key, object(w, "hammer1"), goal(w, "(and (in hammer1 drawer1) (closed drawer1))"), {});
  ASSERT_TRUE(k.has_value()) << k.error().describe();
  EXPECT_EQ(k->literals[0].arguments[1], (GoalTemplateArgument{false, "drawer", {"top"}}));
  EXPECT_THAT(format_goal_knowledge(*k), HasSubstr("(in ?o [top drawer]) and (closed [top drawer])"));
  auto bottom = generalize_goal(w, key, object(w, "hammer1"), goal(w, "(in hammer1 drawer2)"), {});
  ASSERT_TRUE(bottom.has_value());
  EXPECT_EQ(bottom->literals[0].arguments[1].properties, std::vector<std::string>{"bottom"});
  // For another object, the same drawer.
  EXPECT_EQ(text(w, instantiate_goal(w, *k, object(w, "wrench1"))), "(and (in wrench1 drawer1) (closed drawer1))");
  EXPECT_EQ(text(w, instantiate_goal(w, *bottom, object(w, "wrench1"))), "(in wrench1 drawer2)");
  // A unique place is kept by its category alone, whatever its properties.
  auto shelf = generalize_goal(w, key, object(w, "paint-can1"), goal(w, "(on paint-can1 shelf1)"), {});
  ASSERT_TRUE(shelf.has_value());
  EXPECT_TRUE(shelf->literals[0].arguments[1].properties.empty());
  // Where the properties name no place, or two, the template does not guess.
  EXPECT_FALSE(instantiate_goal(world_, *k, object(world_, "ceramic-plate1")).has_value());
}

TEST_F(GoalMemoryTest, InstantiateFailsForAnAbsentCategoryOrUnknownPredicate) {
  GoalKnowledge k = plate_knowledge();
  GoalKnowledge absent = k;
  absent.literals[0].arguments[1].category = "bathtub";
  EXPECT_FALSE(instantiate_goal(world_, absent, object(world_, "ceramic-plate1")).has_value());
  GoalKnowledge unknown = k;
  unknown.literals[1].predicate = "sparkling";
  EXPECT_FALSE(instantiate_goal(world_, unknown, object(world_, "ceramic-plate1")).has_value());
  GoalKnowledge arity = k;
  arity.literals[1].arguments.push_back(GoalTemplateArgument{true, "", {}});
  EXPECT_FALSE(instantiate_goal(world_, arity, object(world_, "ceramic-plate1")).has_value());
  GoalKnowledge ambiguous = k;  // two ceramic plates
  ambiguous.literals[1].arguments[0] = GoalTemplateArgument{false, "ceramic-plate", {}};
  EXPECT_FALSE(instantiate_goal(world_, ambiguous, object(world_, "metal-fork1")).has_value());
}

TEST_F(GoalMemoryTest, NegativeLiteralsSurvive) {
  Goal g = goal(world_, "(and (in ceramic-plate1 dishwasher1) (not (closed dishwasher1)))");
  auto k = generalize_goal(world_, kPlateKey, object(world_, "ceramic-plate1"), g, {});
  ASSERT_TRUE(k.has_value());
  EXPECT_THAT(format_goal_knowledge(*k), HasSubstr("(not (closed dishwasher))"));
  EXPECT_EQ(text(world_, instantiate_goal(world_, *k, object(world_, "ceramic-plate2"))),
            "(and (in ceramic-plate2 dishwasher1) (not (closed dishwasher1)))");
}

TEST_F(GoalMemoryTest, MemoryFindsByKeyAndReplacesTheSameKey) {
  GoalMemory memory;
  EXPECT_EQ(memory.find(kPlateKey), nullptr);
  GoalKnowledge k = plate_knowledge();
  memory.add(k);
  ASSERT_NE(memory.find(kPlateKey), nullptr);
  EXPECT_EQ(*memory.find(kPlateKey), k);
  // Another place or subtask is another key.
  EXPECT_EQ(memory.find(GoalKey{"tidy kitchen", "store", "ceramic-plate", "table"}), nullptr);
  EXPECT_EQ(memory.find(GoalKey{"tidy kitchen", "clear", "ceramic-plate", "counter"}), nullptr);
  GoalKnowledge corrected = k;
  corrected.literals.pop_back();
  memory.add(corrected);
  EXPECT_EQ(memory.size(), 1u);
  EXPECT_EQ(*memory.find(kPlateKey), corrected);
  memory.add(GoalKnowledge{GoalKey{"tidy kitchen", "store", "mug", "counter"}, k.literals, {}});
  EXPECT_EQ(memory.size(), 2u);
}

// The index by key (add, find, remove in O(log n)) against a plain list
// kept beside it: after every step, each key finds the goal last added
// under it, removed keys find nothing, and all() keeps the order of first
// adding.
TEST_F(GoalMemoryTest, TheIndexAgreesWithAPlainListThroughAddsReplacesAndRemoves) {
  GoalMemory memory;
  std::vector<GoalKnowledge> reference;
  const GoalKnowledge k = plate_knowledge();
  unsigned state = 12345;
  auto next = [&] { return state = state * 1103515245u + 12345u, (state >> 16) % 40; };
  for (int step = 0; step < 2000; ++step) {
    const unsigned n = next();
    GoalKnowledge g{GoalKey{"tidy kitchen", n % 2 ? "clear" : "store", "kind-" + std::to_string(n / 2), "table"},
                    k.literals, Provenance{"o" + std::to_string(step), "s"}};
    auto at = std::find_if(reference.begin(), reference.end(), [&](const GoalKnowledge& r) { return r.key == g.key; });
    if (step % 3 == 2) {
      EXPECT_EQ(memory.remove(g.key), at != reference.end());
      if (at != reference.end()) reference.erase(at);
    } else {
      if (at != reference.end()) *at = g;
      else reference.push_back(g);
      memory.add(g);
    }
    ASSERT_EQ(memory.all(), reference) << "step " << step;
    for (const GoalKnowledge& r : reference) {
      ASSERT_NE(memory.find(r.key), nullptr);
      ASSERT_EQ(*memory.find(r.key), r);
    }
    if (step % 3 == 2) {
      EXPECT_EQ(memory.find(g.key), nullptr);
    }
  }
}

}  // namespace
}  // namespace apprentice
