// Goals: reading, writing, and checking them against states.
#include "world/goal.h"

#include <gtest/gtest.h>

#include "world_fixtures.h"

namespace apprentice {
namespace {

using testing::fact;
using testing::load_or_die;
using testing::tidy_kitchen_path;

class Goals : public ::testing::Test {
 protected:
  void SetUp() override { world_ = load_or_die(tidy_kitchen_path()).world; }
  Result<Goal> parse(std::string_view text) const { return parse_goal(*world_.domain, *world_.universe, text); }
  World world_;
};

TEST_F(Goals, ParsesAConjunctionAndWritesItBack) {
  auto goal = parse("(and (in ketchup1 fridge1) (closed fridge1))");
  ASSERT_TRUE(goal.has_value()) << goal.error().describe();
  EXPECT_EQ(goal->literals.size(), 2u);
  std::string text = format_goal(*world_.domain, *world_.universe, *goal);
  auto again = parse(text);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(*again, *goal);
  // Literal order and duplicates do not matter.
  auto swapped = parse("(and (closed fridge1) (in ketchup1 fridge1) (closed fridge1))");
  ASSERT_TRUE(swapped.has_value());
  EXPECT_EQ(*swapped, *goal);
}

TEST_F(Goals, SingleLiteralHasNoAnd) {
  auto goal = parse("(in ketchup1 fridge1)");
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(format_goal(*world_.domain, *world_.universe, *goal), "(in ketchup1 fridge1)");
  auto negative = parse("(not (closed fridge1))");
  ASSERT_TRUE(negative.has_value());
  EXPECT_EQ(format_goal(*world_.domain, *world_.universe, *negative), "(not (closed fridge1))");
}

TEST_F(Goals, SatisfiedByChecksEveryLiteral) {
  auto closed = parse("(closed fridge1)");
  auto open = parse("(not (closed fridge1))");
  auto both = parse("(and (on ketchup1 table1) (closed fridge1))");
  auto unmet = parse("(and (on ketchup1 table1) (in ketchup1 fridge1))");
  ASSERT_TRUE(closed && open && both && unmet);
  EXPECT_TRUE(closed->satisfied_by(world_.state));
  EXPECT_FALSE(open->satisfied_by(world_.state));
  EXPECT_TRUE(both->satisfied_by(world_.state));
  EXPECT_FALSE(unmet->satisfied_by(world_.state));
  EXPECT_TRUE(Goal().satisfied_by(world_.state));
  EXPECT_TRUE(Goal().empty());
}

TEST_F(Goals, ObjectsAreSortedAndUnique) {
  auto goal = parse("(and (in ketchup1 fridge1) (closed fridge1) (on milk1 table1))");
  ASSERT_TRUE(goal.has_value());
  std::vector<ObjectId> expected = {*world_.universe->find("ketchup1"), *world_.universe->find("fridge1"),
                                    *world_.universe->find("milk1"), *world_.universe->find("table1")};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(goal->objects(), expected);
}

TEST_F(Goals, ErrorsNameTheColumnAndWhatWasExpected) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"(in ketchup9 fridge1)", "goal:1:5: expected an object; there is no ketchup9; did you mean ketchup1?"},
      {"(in ketchup fridge1)", "goal:1:5: expected an object; there is no ketchup; did you mean ketchup1?"},
      {"(in wardrobe1 fridge1)", "goal:1:5: expected an object; there is no wardrobe1"},
      {"(inside ketchup1 fridge1)", "goal:1:2: expected a predicate of domain kitchen, not inside"},
      {"(in ketchup1)", "goal:1:1: expected 2 arguments for in"},
      {"(in ketchup1 table1)", "goal:1:14: expected an object of type receptacle; table1 is a surface"},
      {"(and (in ketchup1 fridge1) (closed fridge1)", "goal:1:44: expected ')' to close the list opened at line 1:1"},
      {"(and)", "goal:1:1: expected at least one fact in the goal"},
      {"(not (closed fridge1) x)", "goal:1:1: expected (not (FACT))"},
      {"ketchup1", "goal:1:1: expected a fact such as (closed fridge1)"},
      {"(in ketchup1 fridge1) extra", "goal:1:23: expected the end of the file after the closing ')'"},
  };
  for (const Case& c : cases) {
    auto goal = parse(c.text);
    ASSERT_FALSE(goal.has_value()) << c.text;
    EXPECT_EQ(goal.error().code, ErrorCode::kInvalidInput);
    EXPECT_EQ(goal.error().message, c.message) << c.text;
  }
}

}  // namespace
}  // namespace apprentice
