// The world as the page draws it: every place (surface or receptacle) with
// its door and the things on or in it, and what the robot holds, as JSON.
// Names are the agent's own spoken names ("the top drawer"), so that what
// the page shows is what the agent says.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "world/world.h"

namespace apprentice::serve {

// {"location": "kitchen",
//  "places": [{"id": "fridge1", "name": "fridge", "kind": "receptacle",
//              "door": "closed"|"open"|null, "items": [{"id", "name"}]}],
//  "hand": {"id", "name"} or null}
// Places in the universe's order (surfaces first); items by id.
nlohmann::json world_view(const World& world);

// An object's spoken name without its article: "top drawer", "milk".
std::string bare_name(const World& world, ObjectId object);

}  // namespace apprentice::serve
