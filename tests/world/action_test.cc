// Action semantics on the shipped kitchen domain and the tidy-kitchen
// scenario: preconditions, effects, the one-arm rule, doors, lidless bins,
// and grounding.
#include "world/action.h"

#include <algorithm>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "world_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using testing::action;
using testing::fact;
using testing::load_or_die;
using testing::object;
using testing::tidy_kitchen_path;

class KitchenActions : public ::testing::Test {
 protected:
  void SetUp() override {
    scenario_ = load_or_die(tidy_kitchen_path());
    world_ = scenario_.world;
  }

  const Domain& domain() const { return *world_.domain; }
  const Universe& universe() const { return *world_.universe; }

  std::optional<std::string> why_not(const State& state, std::string_view text) const {
    return why_not_applicable(domain(), universe(), state, action(world_, text));
  }
  bool applicable(const State& state, std::string_view text) const {
    return is_applicable(domain(), state, action(world_, text));
  }
  // Applies a sequence of actions, each of which must be applicable.
  State after(std::initializer_list<std::string_view> steps) const {
    State state = world_.state;
    for (std::string_view step : steps) {
      auto reason = why_not(state, step);
      EXPECT_FALSE(reason.has_value()) << step << ": " << *reason;
      if (reason) return state;
      state = apply(domain(), state, action(world_, step));
    }
    return state;
  }
  bool holds(const State& state, std::string_view text) const { return state.holds(fact(world_, text)); }

  Scenario scenario_;
  World world_;
};

TEST_F(KitchenActions, InitialStateIsAsTheScenarioSays) {
  const State& s = world_.state;
  EXPECT_TRUE(holds(s, "(handempty)"));
  EXPECT_TRUE(holds(s, "(on ketchup1 table1)"));
  EXPECT_TRUE(holds(s, "(in mug2 dish-rack1)"));
  EXPECT_TRUE(holds(s, "(closed fridge1)"));
  EXPECT_TRUE(holds(s, "(openable fridge1)"));
  EXPECT_FALSE(holds(s, "(openable sink1)"));
  EXPECT_FALSE(holds(s, "(closed sink1)"));
}

TEST_F(KitchenActions, OpenNeedsAClosedOpenableReceptacleAndAnEmptyHand) {
  EXPECT_EQ(why_not(world_.state, "(open fridge1)"), std::nullopt);
  State opened = after({"(open fridge1)"});
  EXPECT_FALSE(holds(opened, "(closed fridge1)"));
  EXPECT_TRUE(holds(opened, "(handempty)"));
  // Already open.
  EXPECT_EQ(why_not(opened, "(open fridge1)"), "(closed fridge1) is false");
  // No door.
  EXPECT_EQ(why_not(world_.state, "(open sink1)"), "(openable sink1) is false");
  EXPECT_EQ(why_not(world_.state, "(open dish-rack1)"), "(openable dish-rack1) is false");
}

TEST_F(KitchenActions, CloseNeedsAnOpenDoorAndAnEmptyHand) {
  EXPECT_EQ(why_not(world_.state, "(close fridge1)"), "(closed fridge1) is true");
  State opened = after({"(open fridge1)"});
  EXPECT_EQ(why_not(opened, "(close fridge1)"), std::nullopt);
  State closed = after({"(open fridge1)", "(close fridge1)"});
  EXPECT_EQ(closed, world_.state);
}

TEST_F(KitchenActions, OneArmRuleHoldingSomethingForbidsOpening) {
  State holding = after({"(pick-up ketchup1 table1)"});
  EXPECT_TRUE(holds(holding, "(holding ketchup1)"));
  EXPECT_FALSE(holds(holding, "(handempty)"));
  EXPECT_EQ(why_not(holding, "(open fridge1)"), "(handempty) is false");
  EXPECT_FALSE(applicable(holding, "(open fridge1)"));
}

TEST_F(KitchenActions, OneArmRuleHoldingSomethingForbidsClosing) {
  State holding = after({"(open fridge1)", "(pick-up ketchup1 table1)"});
  EXPECT_EQ(why_not(holding, "(close fridge1)"), "(handempty) is false");
  State done = after({"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)"});
  EXPECT_EQ(why_not(done, "(close fridge1)"), std::nullopt);
}

TEST_F(KitchenActions, OneArmRuleCannotPickUpTwoThings) {
  State holding = after({"(pick-up ketchup1 table1)"});
  EXPECT_EQ(why_not(holding, "(pick-up milk1 table1)"), "(handempty) is false");
  EXPECT_EQ(why_not(holding, "(pick-up-from mug2 dish-rack1)"), "(handempty) is false");
}

TEST_F(KitchenActions, PickUpMovesTheItemIntoTheHand) {
  State holding = after({"(pick-up ketchup1 table1)"});
  EXPECT_FALSE(holds(holding, "(on ketchup1 table1)"));
  EXPECT_TRUE(holds(holding, "(holding ketchup1)"));
  EXPECT_FALSE(holds(holding, "(handempty)"));
  EXPECT_EQ(holding.size(), world_.state.size() - 1);  // -on -handempty +holding
  EXPECT_EQ(why_not(world_.state, "(pick-up ketchup1 counter1)"), "(on ketchup1 counter1) is false");
}

TEST_F(KitchenActions, CannotPickUpFromAClosedReceptacle) {
  State stored = after({"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                        "(close fridge1)"});
  EXPECT_TRUE(holds(stored, "(in ketchup1 fridge1)"));
  EXPECT_TRUE(holds(stored, "(closed fridge1)"));
  EXPECT_EQ(why_not(stored, "(pick-up-from ketchup1 fridge1)"), "(closed fridge1) is true");
  State reopened = after({"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                          "(close fridge1)", "(open fridge1)"});
  EXPECT_EQ(why_not(reopened, "(pick-up-from ketchup1 fridge1)"), std::nullopt);
}

TEST_F(KitchenActions, PickUpFromAnOpenReceptacleWithoutDoor) {
  State holding = after({"(pick-up-from mug2 dish-rack1)"});
  EXPECT_TRUE(holds(holding, "(holding mug2)"));
  EXPECT_FALSE(holds(holding, "(in mug2 dish-rack1)"));
  // pick-up is for surfaces, pick-up-from for receptacles: the types say so.
  auto wrong = parse_action(domain(), universe(), "(pick-up mug2 dish-rack1)");
  ASSERT_FALSE(wrong.has_value());
  EXPECT_THAT(wrong.error().message, HasSubstr("expected a surface"));
}

TEST_F(KitchenActions, PutInRequiresAnOpenReceptacle) {
  State holding = after({"(pick-up ketchup1 table1)"});
  EXPECT_EQ(why_not(holding, "(put-in ketchup1 fridge1)"), "(closed fridge1) is true");
  EXPECT_EQ(why_not(holding, "(put-in ketchup1 sink1)"), std::nullopt);
  EXPECT_EQ(why_not(holding, "(put-on ketchup1 counter1)"), std::nullopt);
  EXPECT_EQ(why_not(holding, "(put-in milk1 sink1)"), "(holding milk1) is false");
  State put = after({"(pick-up ketchup1 table1)", "(put-on ketchup1 counter1)"});
  EXPECT_TRUE(holds(put, "(on ketchup1 counter1)"));
  EXPECT_TRUE(holds(put, "(handempty)"));
  EXPECT_FALSE(holds(put, "(holding ketchup1)"));
}

TEST_F(KitchenActions, LidlessBinsAreNeverOpenableOrClosable) {
  for (std::string_view bin : {"recycling-bin1", "garbage1", "sink1", "dish-rack1"}) {
    std::string name(bin);
    EXPECT_FALSE(holds(world_.state, "(openable " + name + ")")) << name;
    EXPECT_FALSE(holds(world_.state, "(closed " + name + ")")) << name;
    EXPECT_EQ(why_not(world_.state, "(open " + name + ")"), "(openable " + name + ") is false");
    EXPECT_EQ(why_not(world_.state, "(close " + name + ")"), "(openable " + name + ") is false");
  }
  // Nor do they become so after other actions: grounding drops them for good.
  ObjectId recycling = object(world_, "recycling-bin1");
  ObjectId garbage = object(world_, "garbage1");
  std::vector<ObjectId> all(universe().size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<ObjectId>(i);
  for (const Action& a : ground_actions(domain(), universe(), all, world_.state)) {
    const std::string& name = domain().actions[a.schema].name;
    if (name == "open" || name == "close") {
      EXPECT_NE(a.args[0], recycling);
      EXPECT_NE(a.args[0], garbage);
    }
  }
}

TEST_F(KitchenActions, TypeErrorsAreReportedNotApplied) {
  Action bad(*domain().find_action("open"), std::vector<ObjectId>{object(world_, "ketchup1")});
  EXPECT_EQ(why_not_applicable(domain(), universe(), world_.state, bad), "ketchup1 is not a receptacle");
  Action short_one(*domain().find_action("put-in"), std::vector<ObjectId>{object(world_, "ketchup1")});
  EXPECT_EQ(why_not_applicable(domain(), universe(), world_.state, short_one), "put-in takes 2 arguments");
}

TEST_F(KitchenActions, InstantiatedPreconditionsAndEffects) {
  Action put_in = action(world_, "(put-in ketchup1 fridge1)");
  std::vector<Literal> pre = preconditions_of(domain(), put_in);
  ASSERT_EQ(pre.size(), 3u);
  EXPECT_EQ(pre[0], (Literal{fact(world_, "(receptacle fridge1)"), true}));
  EXPECT_EQ(pre[1], (Literal{fact(world_, "(holding ketchup1)"), true}));
  EXPECT_EQ(pre[2], (Literal{fact(world_, "(closed fridge1)"), false}));
  EXPECT_EQ(add_effects_of(domain(), put_in),
            (std::vector<Fact>{fact(world_, "(in ketchup1 fridge1)"), fact(world_, "(handempty)")}));
  EXPECT_EQ(delete_effects_of(domain(), put_in), (std::vector<Fact>{fact(world_, "(holding ketchup1)")}));
}

TEST_F(KitchenActions, FormatAndParseRoundTrip) {
  for (std::string_view text : {"(open fridge1)", "(pick-up ketchup1 table1)", "(pick-up-from mug2 dish-rack1)",
                                "(put-on mug1 counter1)", "(put-in ketchup1 fridge1)", "(close drawer1)"}) {
    EXPECT_EQ(format_action(domain(), universe(), action(world_, text)), text);
  }
  // Case and spacing do not matter to the reader.
  auto loose = parse_action(domain(), universe(), "  ( OPEN   Fridge1 ) ");
  ASSERT_TRUE(loose.has_value());
  EXPECT_EQ(format_action(domain(), universe(), *loose), "(open fridge1)");
}

TEST_F(KitchenActions, ParseActionErrors) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"(fly fridge1)", "action:1:2: expected an action of domain kitchen, not fly"},
      {"(open)", "action:1:1: expected 1 arguments for open"},
      {"(open fridge1 table1)", "action:1:1: expected 1 arguments for open"},
      {"(open fridge9)", "action:1:7: expected an object; there is no fridge9; did you mean fridge1?"},
      {"(open wardrobe1)", "action:1:7: expected an object; there is no wardrobe1"},
      {"(open table1)", "action:1:7: expected a receptacle; table1 is not one"},
      {"open", "action:1:1: expected an action such as (open fridge1)"},
      {"(open fridge1", "action:1:14: expected ')' to close the list opened at line 1:1"},
      {"", "action:1:1: expected '(' but the file is empty"},
  };
  for (const Case& c : cases) {
    auto parsed = parse_action(domain(), universe(), c.text);
    ASSERT_FALSE(parsed.has_value()) << c.text;
    EXPECT_EQ(parsed.error().code, ErrorCode::kInvalidInput) << c.text;
    EXPECT_EQ(parsed.error().message, c.message) << c.text;
  }
}

TEST_F(KitchenActions, GroundingCountsAndOrder) {
  std::vector<ObjectId> all(universe().size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<ObjectId>(i);
  std::vector<Action> actions = ground_actions(domain(), universe(), all, world_.state);
  const std::size_t items = universe().of_kind(ObjectKind::kItem).size();
  const std::size_t surfaces = universe().of_kind(ObjectKind::kSurface).size();
  const std::size_t receptacles = universe().of_kind(ObjectKind::kReceptacle).size();
  ASSERT_EQ(items, 30u);
  ASSERT_EQ(surfaces, 2u);
  ASSERT_EQ(receptacles, 9u);
  const std::size_t doors = 5;
  // open + close over doors, pick-up/put-on over item x surface,
  // pick-up-from/put-in over item x receptacle.
  EXPECT_EQ(actions.size(), 2 * doors + 2 * items * surfaces + 2 * items * receptacles);
  EXPECT_TRUE(std::is_sorted(actions.begin(), actions.end()));
  EXPECT_EQ(std::adjacent_find(actions.begin(), actions.end()), actions.end());
  // Grounding over a shuffled, duplicated object list gives the same actions.
  std::vector<ObjectId> messy(all.rbegin(), all.rend());
  messy.insert(messy.end(), all.begin(), all.begin() + 5);
  EXPECT_EQ(ground_actions(domain(), universe(), messy, world_.state), actions);
  // Every ground action is well typed, and is_applicable agrees with
  // why_not_applicable in a few states.
  for (const State& state : {world_.state, after({"(open fridge1)"}), after({"(pick-up ketchup1 table1)"})}) {
    for (const Action& a : actions) {
      auto reason = why_not_applicable(domain(), universe(), state, a);
      EXPECT_EQ(is_applicable(domain(), state, a), !reason.has_value()) << format_action(domain(), universe(), a);
      if (reason) {
        EXPECT_THAT(*reason, ::testing::AnyOf(HasSubstr(" is false"), HasSubstr(" is true")));
      }
    }
  }
}

TEST_F(KitchenActions, GroundingOverASubsetMentionsOnlyThatSubset) {
  std::vector<ObjectId> some = {object(world_, "ketchup1"), object(world_, "fridge1"), object(world_, "table1"),
                                object(world_, "sink1")};
  std::vector<Action> actions = ground_actions(domain(), universe(), some, world_.state);
  std::set<std::string> names;
  for (const Action& a : actions) names.insert(format_action(domain(), universe(), a));
  EXPECT_EQ(names, (std::set<std::string>{"(open fridge1)", "(close fridge1)", "(pick-up ketchup1 table1)",
                                          "(pick-up-from ketchup1 fridge1)", "(pick-up-from ketchup1 sink1)",
                                          "(put-on ketchup1 table1)", "(put-in ketchup1 fridge1)",
                                          "(put-in ketchup1 sink1)"}));
}

}  // namespace
}  // namespace apprentice
