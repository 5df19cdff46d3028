// A TidyBot scenario as a world the agent can act in, in the kitchen
// domain (data/domains/kitchen.pddl): the room's receptacles as places and
// the objects on a cart, where the robot has gathered them; the task
// "tidy <room>" with one subtask, clearing the cart; and, for the
// simulated teacher and the scoring only, where the person wants each
// object (the scenario's intent).
//
// Names become the world's words as a person would say them: "Rubik's
// cube" is the category rubiks-cube ("the rubiks cube"); "left storage
// box" is a storage-box with the property left, told apart from the right
// one as every look-alike place is (docs/scenarios.md); a receptacle is a
// place things go in when WordNet calls it a container or a storage space
// (basket, drawer, closet), or says things are stored in it or that it is
// a basin (cabinet, refrigerator, sink); otherwise a surface things go on
// (shelf, sofa, coffee table). A second object of a kind ("pillow 2" beside "pillow",
// going to the same place) is another object of that kind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "benchmark/tidybot_scenarios.h"
#include "language/lexicon.h"
#include "world/scenario.h"

namespace apprentice::benchmark {

// The category a benchmark object becomes: lower case, apostrophes
// dropped, other punctuation and spaces as hyphens ("Cheez-It crackers"
// -> cheez-it-crackers).
std::string item_category(std::string_view name);

// A receptacle's category and properties: leading words that tell
// look-alikes apart by position or size (left, top, middle, small, big,
// ...) are properties when a noun is left after them ("top drawer" ->
// drawer [top]); the rest is the category ("bin 1" -> bin-1, "coffee
// table" -> coffee-table).
struct PlaceName {
  std::string category;
  std::vector<std::string> properties;
};
PlaceName place_name(std::string_view receptacle);

struct BenchmarkWorld {
  Scenario scenario;  // world, task ("tidy <room>", clearing the cart) and intent
  ObjectId cart = 0;  // where every object starts
  // The benchmark's names with the world's objects, in the benchmark's order.
  std::vector<std::pair<std::string, ObjectId>> objects;
  std::vector<std::pair<std::string, ObjectId>> places;

  // The benchmark's receptacle name of a place; empty for the cart.
  std::string receptacle_name(ObjectId place) const;
};

// The world holding `objects` (some of the scenario's, each going where the
// scenario says), in `domain` (a PDDL file with the kitchen's types).
// The lexicon tells receptacles from surfaces (without WordNet every place
// is a surface). Errors: those of parse_scenario, naming the scenario.
Result<BenchmarkWorld> build_world(const TidyBotScenario& scenario, const std::vector<std::string>& objects,
                                   const std::filesystem::path& domain,
                                   const language::Lexicon& lexicon);

}  // namespace apprentice::benchmark
