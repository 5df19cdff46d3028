// Relevance pruning: which objects search grounds over, and the projected
// state it searches from.
#include "search/relevance.h"

#include <gtest/gtest.h>

#include "search_fixtures.h"

namespace apprentice {
namespace {

using testing::goal_or_die;

std::vector<std::string> names(const Universe& universe, const std::vector<ObjectId>& ids) {
  std::vector<std::string> out;
  for (ObjectId id : ids) out.push_back(universe.name(id));
  std::sort(out.begin(), out.end());
  return out;
}

class Relevance : public ::testing::Test {
 protected:
  void SetUp() override { world_ = testing::tidy_kitchen().world; }
  World world_;
};

TEST_F(Relevance, GoalObjectsAndEveryPlace) {
  Goal goal = goal_or_die(world_, "(and (in ketchup1 fridge1) (closed fridge1))");
  std::vector<ObjectId> relevant = relevant_objects(*world_.domain, *world_.universe, world_.state, goal);
  EXPECT_TRUE(std::is_sorted(relevant.begin(), relevant.end()));
  EXPECT_EQ(names(*world_.universe, relevant),
            (std::vector<std::string>{"counter1", "cupboard1", "dish-rack1", "dishwasher1", "drawer1", "fridge1",
                                      "garbage1", "ketchup1", "pantry1", "recycling-bin1", "sink1", "table1"}));
}

TEST_F(Relevance, TheItemInHandIsRelevant) {
  State holding = apply(*world_.domain, world_.state,
                        *parse_action(*world_.domain, *world_.universe, "(pick-up milk1 table1)"));
  Goal goal = goal_or_die(world_, "(closed fridge1)");
  std::vector<ObjectId> relevant = relevant_objects(*world_.domain, *world_.universe, holding, goal);
  auto n = names(*world_.universe, relevant);
  EXPECT_NE(std::find(n.begin(), n.end(), "milk1"), n.end());
  EXPECT_EQ(std::find(n.begin(), n.end(), "ketchup1"), n.end());
  EXPECT_EQ(n.size(), 12u);
}

TEST_F(Relevance, ProjectionKeepsOnlyFactsOverRelevantObjects) {
  Goal goal = goal_or_die(world_, "(in ketchup1 fridge1)");
  std::vector<ObjectId> relevant = relevant_objects(*world_.domain, *world_.universe, world_.state, goal);
  State projected = project_state(world_.state, relevant);
  EXPECT_LT(projected.size(), world_.state.size());
  for (const Fact& f : projected.facts()) {
    EXPECT_TRUE(world_.state.holds(f));
    for (ObjectId o : f.arguments()) EXPECT_TRUE(std::binary_search(relevant.begin(), relevant.end(), o));
  }
  for (const Fact& f : world_.state.facts()) {
    bool all_relevant = true;
    for (ObjectId o : f.arguments())
      if (!std::binary_search(relevant.begin(), relevant.end(), o)) all_relevant = false;
    EXPECT_EQ(projected.holds(f), all_relevant);
  }
  // Zero-argument facts always survive.
  EXPECT_TRUE(projected.holds(Fact(world_.vocabulary.handempty, std::initializer_list<ObjectId>{})));
  // Projecting onto everything changes nothing.
  std::vector<ObjectId> all(world_.universe->size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<ObjectId>(i);
  EXPECT_EQ(project_state(world_.state, all), world_.state);
}

}  // namespace
}  // namespace apprentice
