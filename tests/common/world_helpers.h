// Naming objects, actions and goals in tests; each helper fails the test
// when the text does not read, so that a test body stays about behaviour.
#pragma once

#include <string_view>

#include "common/scenarios.h"
#include "world/action.h"
#include "world/goal.h"

namespace apprentice::testing {

// "fridge1" -> its ObjectId (0, with a test failure, if there is none).
ObjectId object(const World& world, std::string_view id);
// "(open fridge1)" -> the Action, checked.
Action action(const World& world, std::string_view text);
// "(and (in mug1 cupboard1) (closed cupboard1))" -> the Goal, checked.
Goal goal(const World& world, std::string_view text);

}  // namespace apprentice::testing
