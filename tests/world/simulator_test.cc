// The simulator executes only applicable actions; a refused action leaves
// the state and the history untouched.
#include "world/simulator.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "world_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using testing::action;
using testing::fact;
using testing::load_or_die;
using testing::tidy_kitchen_path;

class SimulatorTest : public ::testing::Test {
 protected:
  void SetUp() override { world_ = load_or_die(tidy_kitchen_path()).world; }
  World world_;
};

TEST_F(SimulatorTest, ExecutesTheKetchupPlan) {
  Simulator sim(world_);
  for (const char* step : {"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                           "(close fridge1)"}) {
    Status status = sim.execute(action(world_, step));
    ASSERT_TRUE(status.has_value()) << step << ": " << status.error().describe();
  }
  EXPECT_TRUE(sim.state().holds(fact(world_, "(in ketchup1 fridge1)")));
  EXPECT_TRUE(sim.state().holds(fact(world_, "(closed fridge1)")));
  EXPECT_TRUE(sim.state().holds(fact(world_, "(handempty)")));
  EXPECT_EQ(sim.history().size(), 4u);
  EXPECT_EQ(sim.world().state, sim.state());
  // The world it was built from is a separate value.
  EXPECT_TRUE(world_.state.holds(fact(world_, "(on ketchup1 table1)")));
}

TEST_F(SimulatorTest, RefusesAndLeavesTheStateUnchanged) {
  Simulator sim(world_);
  State before = sim.state();
  Status status = sim.execute(action(world_, "(put-in ketchup1 fridge1)"));
  ASSERT_FALSE(status.has_value());
  EXPECT_EQ(status.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_EQ(status.error().message, "cannot (put-in ketchup1 fridge1): (holding ketchup1) is false");
  EXPECT_EQ(sim.state(), before);
  EXPECT_TRUE(sim.history().empty());
}

TEST_F(SimulatorTest, OneArmRulePickingUpFirstBlocksOpeningTheFridge) {
  // The robot must open the fridge before it picks up the ketchup.
  Simulator sim(world_);
  ASSERT_TRUE(sim.execute(action(world_, "(pick-up ketchup1 table1)")).has_value());
  State holding = sim.state();
  Status open = sim.execute(action(world_, "(open fridge1)"));
  ASSERT_FALSE(open.has_value());
  EXPECT_EQ(open.error().message, "cannot (open fridge1): (handempty) is false");
  EXPECT_EQ(sim.state(), holding);
  EXPECT_EQ(sim.history().size(), 1u);
  // Putting it into the closed fridge is refused too.
  Status put = sim.execute(action(world_, "(put-in ketchup1 fridge1)"));
  ASSERT_FALSE(put.has_value());
  EXPECT_THAT(put.error().message, HasSubstr("(closed fridge1) is true"));
  EXPECT_EQ(sim.state(), holding);
}

TEST_F(SimulatorTest, RefusesIllTypedActions) {
  Simulator sim(world_);
  Action bad(*world_.domain->find_action("open"), std::vector<ObjectId>{*world_.universe->find("table1")});
  Status status = sim.execute(bad);
  ASSERT_FALSE(status.has_value());
  EXPECT_EQ(status.error().message, "cannot (open table1): table1 is not a receptacle");
  EXPECT_EQ(sim.state(), world_.state);
}

}  // namespace
}  // namespace apprentice
