// What the robot perceives: the action model, the objects and the state.
// This is all the agent is given of a scenario. The task structure reaches
// it only through the instructor's words, and the intent (what the
// instructor wants, world/scenario.h) never does: scripts/check-layers.py
// fails if the agent, knowledge or search reach world/scenario.h.
#pragma once

#include <memory>
#include <string>

#include "world/domain.h"
#include "world/state.h"
#include "world/universe.h"
#include "world/vocabulary.h"

namespace apprentice {

// A value: copies share the immutable domain and universe and copy the
// state, so each Simulator works on its own copy.
struct World {
  std::shared_ptr<const Domain> domain;
  Vocabulary vocabulary;
  std::shared_ptr<const Universe> universe;
  State state;
  std::string location;  // where the robot is: "kitchen"
};

}  // namespace apprentice
